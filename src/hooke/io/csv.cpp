#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <hooke/core/atomic_file.hpp>
#include <hooke/core/error.hpp>
#include <hooke/io/csv.hpp>
#include <iomanip>

namespace hooke::io {

void write_node_csv(const std::filesystem::path& path, const mesh::Mesh& m, const std::vector<Field>& fields) {
  for (const Field& f : fields)
    if (f.values.size() != static_cast<Eigen::Index>(m.node_count()) * f.components)
      throw InvalidArgument("field '" + f.name + "' does not have one value set per node");
  require_finite_positions(m.nodes, path);
  for (const Field& f : fields) require_finite(f, path);
  write_file_atomically(path, [&](std::ostream& out) {
    static const char* kAxis[] = {"x", "y", "z"};
    out << "node";
    for (int c = 0; c < m.dim(); ++c) out << ',' << kAxis[c];
    for (const Field& f : fields)
      for (int c = 0; c < f.components; ++c) {
        out << ',' << f.name;
        if (f.components > 1) {
          out << '_';
          if (c < 3)
            out << kAxis[c];
          else
            out << c;
        }
      }
    out << '\n' << std::setprecision(12);
    for (int i = 0; i < m.node_count(); ++i) {
      out << i;
      for (int c = 0; c < m.dim(); ++c) out << ',' << m.nodes(i, c);
      for (const Field& f : fields)
        for (int c = 0; c < f.components; ++c) out << ',' << f.values(f.components * i + c);
      out << '\n';
    }
  });
}

int CsvTable::column(const std::string& name) const {
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c] == name) return static_cast<int>(c);
  return -1;
}

namespace {
std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r"), e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}
std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t comma; (comma = line.find(',', start)) != std::string::npos; start = comma + 1)
    out.push_back(trimmed(line.substr(start, comma - start)));
  out.push_back(trimmed(line.substr(start)));
  return out;
}
}  // namespace

CsvTable read_csv_table(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw IoError("cannot read " + path.string());
  const std::string file = path.string();
  CsvTable t;
  std::vector<double> values;
  std::string line;
  std::int64_t number = 0, rows = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::string body = trimmed(line);
    if (body.empty() || body[0] == '#') continue;
    std::vector<std::string> tokens = split(body);
    if (t.columns.empty()) {
      t.columns = std::move(tokens);
      continue;
    }
    if (tokens.size() != t.columns.size())
      throw ParseError(file, number,
                       std::to_string(tokens.size()) + " values where the header has " +
                           std::to_string(t.columns.size()) + " columns");
    for (std::size_t c = 0; c < tokens.size(); ++c) {
      errno = 0;
      char* end = nullptr;
      const double v = std::strtod(tokens[c].c_str(), &end);
      if (tokens[c].empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
        throw ParseError(file, number, "column '" + t.columns[c] + "': '" + tokens[c] + "' is not a finite number");
      values.push_back(v);
    }
    ++rows;
  }
  if (in.bad()) throw IoError("error reading " + file);
  if (t.columns.empty() || rows == 0) throw ParseError(file, number, "no header line and rows of numbers");
  t.values = Eigen::Map<const RowMatX>(values.data(), static_cast<Eigen::Index>(rows),
                                       static_cast<Eigen::Index>(t.columns.size()));
  return t;
}

}  // namespace hooke::io
