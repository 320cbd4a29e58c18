#pragma once
/// The library never prints: every message goes through one replaceable sink.
#include <functional>
#include <string_view>

namespace hooke {

enum class LogLevel { kDebug, kInfo, kWarning, kError };

/// Receives every message the library emits.
using LogSink = std::function<void(LogLevel level, std::string_view message)>;

/// Replaces the sink and returns the previous one (to restore it); an empty function silences the library.
/// The default writes warnings and errors to stderr.
LogSink set_log_sink(LogSink sink);

/// Sends one message to the current sink.
void log(LogLevel level, std::string_view message);

/// Shorthand for log(LogLevel::kWarning, message).
inline void log_warning(std::string_view message) { log(LogLevel::kWarning, message); }

}  // namespace hooke
