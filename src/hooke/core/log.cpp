#include <hooke/core/log.hpp>

#include <cstdio>
#include <mutex>

namespace hooke {
namespace {

void default_sink(LogLevel level, std::string_view message) {
  if (level < LogLevel::kWarning) return;
  const char* tag = level == LogLevel::kWarning ? "warning" : "error";
  std::fprintf(stderr, "hooke: %s: %.*s\n", tag, static_cast<int>(message.size()), message.data());
}

// The one piece of process-wide state: the log sink (one replaceable sink).
LogSink& sink() {
  static LogSink current = default_sink;
  return current;
}
std::mutex& sink_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace

LogSink set_log_sink(LogSink new_sink) {
  std::lock_guard lock(sink_mutex());
  LogSink old = std::move(sink());
  sink() = std::move(new_sink);
  return old;
}

void log(LogLevel level, std::string_view message) {
  std::lock_guard lock(sink_mutex());
  if (sink()) sink()(level, message);
}

}  // namespace hooke
