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

}  // namespace hooke::io
