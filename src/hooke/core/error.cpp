#include <hooke/core/error.hpp>

namespace hooke {

ParseError::ParseError(std::string file, std::int64_t line, const std::string& what_failed)
    : ParseError(file, line, -1, file + ":" + std::to_string(line) + ": " + what_failed) {}

ParseError::ParseError(std::string file, std::int64_t line, std::int64_t byte_offset, const std::string& message)
    : Error(message), m_file(std::move(file)), m_line(line), m_byte_offset(byte_offset) {}

ParseError ParseError::at_byte(std::string file, std::int64_t byte_offset, const std::string& what_failed) {
  std::string message = file + ": at byte " + std::to_string(byte_offset) + ": " + what_failed;
  return ParseError(std::move(file), 0, byte_offset, message);
}

ParseError ParseError::at_entry(std::string file, const std::string& entry, const std::string& what_failed) {
  std::string message = file + ": " + entry + ": " + what_failed;
  return ParseError(std::move(file), 0, -1, message);
}

}  // namespace hooke
