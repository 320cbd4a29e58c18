#pragma once
// A whole file in memory with a cursor, for parsers that mix text tokens and binary blocks (MSH) or are
// plain text (TetGen, OFF, STL, VTU). Errors name the file and the line (text) or the byte (binary).
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <hooke/core/error.hpp>
#include <string>
#include <string_view>

namespace hooke::io::detail {

class Reader {
 public:
  Reader(std::string name, std::string content)
      : m_name(std::move(name)), m_data(std::move(content)), m_end(m_data.size()) {}
  static Reader open(const std::filesystem::path& path);

  const std::string& name() const { return m_name; }
  const std::string& data() const { return m_data; }
  size_t offset() const { return m_pos; }
  std::int64_t line() const;  // 1-based line of the cursor
  bool at_end() const { return m_pos >= m_end; }
  // Bytes left after the cursor (before the end of the window, see `window`).
  size_t remaining() const { return m_pos < m_end ? m_end - m_pos : 0; }
  // Confines reading to bytes [begin, end) of the file, the cursor at `begin`, without copying (a section of an XML
  // file); window(0, data().size()) lifts it. Errors still name the file's line.
  void window(size_t begin, size_t end) {
    m_end = std::min(end, m_data.size());
    m_pos = std::min(begin, m_end);
  }
  // A count declared by the file, checked before anything is allocated or skipped for it: `count` items of at least
  // `min_bytes` bytes each must fit in the bytes left (no multiplication, so no wrap-around). Fails naming `what`.
  std::uint64_t bounded_count(std::uint64_t count, size_t min_bytes, const char* what) const {
    if (min_bytes > 0 && count > remaining() / min_bytes)
      fail(std::string(what) + " " + std::to_string(count) + " cannot fit in the " + std::to_string(remaining()) +
           " bytes left in the file (it is truncated, or the count is wrong)");
    return count;
  }

  [[noreturn]] void fail(const std::string& what) const { throw ParseError(m_name, line(), what); }
  // Error naming the line that holds byte `offset`.
  [[noreturn]] void fail_at_offset(size_t offset, const std::string& what) const;
  [[noreturn]] void fail_at_byte(const std::string& what) const {
    throw ParseError::at_byte(m_name, static_cast<std::int64_t>(m_pos), what);
  }

  // Skips blanks and newlines, and comments starting with `comment` (if non-zero) up to the end of line.
  void skip_space(char comment = 0);
  // Next whitespace-delimited token; empty at the end of the file.
  std::string_view token(char comment = 0);
  // Next token, which must exist; `what` names it in the error.
  std::string_view expect_token(const char* what, char comment = 0);
  double number(const char* what, char comment = 0);
  std::int64_t integer(const char* what, char comment = 0);
  // Rest of the current line (without the newline), and moves past it.
  std::string_view rest_of_line();
  // True when only blanks remain before the end of the current line.
  bool at_end_of_line() const;
  // Moves past the next newline.
  void skip_line();

  // Binary access at the cursor (little-endian host assumed, as the formats' own writers produce).
  template <typename T>
  T binary(const char* what) {
    if (sizeof(T) > remaining()) fail_at_byte(std::string("file ends inside ") + what);
    T v;
    std::memcpy(&v, m_data.data() + m_pos, sizeof(T));
    m_pos += sizeof(T);
    return v;
  }
  void skip_bytes(size_t n, const char* what) {
    if (n > remaining()) fail_at_byte(std::string("file ends inside ") + what);
    m_pos += n;
  }

 private:
  std::string m_name;
  std::string m_data;
  size_t m_end;  // the end of the window
  size_t m_pos = 0;
  mutable size_t m_counted_to = 0;              // line(): newlines before this offset are counted
  mutable std::int64_t m_counted_newlines = 0;  // in m_counted_newlines
};

}  // namespace hooke::io::detail
