#include <algorithm>
#include <charconv>
#include <fstream>
#include <hooke/io/detail/reader.hpp>
#include <sstream>

namespace hooke::io::detail {

Reader Reader::open(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot open '" + path.string() + "'");
  std::ostringstream ss;
  ss << in.rdbuf();
  return Reader(path.string(), ss.str());
}

// Counts newlines from the last position asked about (readers ask in increasing order), so that asking for the line
// of every record is linear in the file size, not quadratic (a 2.7 MB OBJ took 58 s when it was quadratic).
std::int64_t Reader::line() const {
  const size_t pos = std::min(m_pos, m_data.size());
  if (pos < m_counted_to) {
    m_counted_to = 0;
    m_counted_newlines = 0;
  }
  m_counted_newlines += std::count(m_data.begin() + static_cast<std::ptrdiff_t>(m_counted_to),
                                   m_data.begin() + static_cast<std::ptrdiff_t>(pos), '\n');
  m_counted_to = pos;
  return 1 + m_counted_newlines;
}

void Reader::fail_at_offset(size_t offset, const std::string& what) const {
  const auto end = m_data.begin() + static_cast<std::ptrdiff_t>(std::min(offset, m_data.size()));
  throw ParseError(m_name, 1 + std::count(m_data.begin(), end, '\n'), what);
}

void Reader::skip_space(char comment) {
  while (m_pos < m_end) {
    const char c = m_data[m_pos];
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
      ++m_pos;
    } else if (comment != 0 && c == comment) {
      while (m_pos < m_end && m_data[m_pos] != '\n') ++m_pos;
    } else {
      break;
    }
  }
}

std::string_view Reader::token(char comment) {
  skip_space(comment);
  const size_t start = m_pos;
  while (m_pos < m_end) {
    const char c = m_data[m_pos];
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || (comment != 0 && c == comment)) break;
    ++m_pos;
  }
  return std::string_view(m_data).substr(start, m_pos - start);
}

std::string_view Reader::expect_token(const char* what, char comment) {
  const std::string_view t = token(comment);
  if (t.empty()) fail(std::string("file ends where ") + what + " was expected");
  return t;
}

double Reader::number(const char* what, char comment) {
  const std::string_view t = expect_token(what, comment);
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || ptr != t.data() + t.size())
    fail(std::string("expected ") + what + " (a number), found '" + std::string(t) + "'");
  return v;
}

std::int64_t Reader::integer(const char* what, char comment) {
  const std::string_view t = expect_token(what, comment);
  std::int64_t v = 0;
  const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || ptr != t.data() + t.size())
    fail(std::string("expected ") + what + " (an integer), found '" + std::string(t) + "'");
  return v;
}

std::string_view Reader::rest_of_line() {
  const size_t start = m_pos;
  while (m_pos < m_end && m_data[m_pos] != '\n') ++m_pos;
  std::string_view s = std::string_view(m_data).substr(start, m_pos - start);
  if (m_pos < m_end) ++m_pos;
  if (!s.empty() && s.back() == '\r') s.remove_suffix(1);
  return s;
}

bool Reader::at_end_of_line() const {
  for (size_t p = m_pos; p < m_end; ++p) {
    if (m_data[p] == '\n') return true;
    if (m_data[p] != ' ' && m_data[p] != '\t' && m_data[p] != '\r') return false;
  }
  return true;
}

void Reader::skip_line() { rest_of_line(); }

}  // namespace hooke::io::detail
