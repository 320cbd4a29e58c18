#include <charconv>
#include <hooke/core/atomic_file.hpp>
#include <hooke/io/detail/assemble.hpp>
#include <hooke/io/detail/reader.hpp>
#include <hooke/io/obj.hpp>
#include <iomanip>
#include <vector>

namespace hooke::io {

mesh::Mesh read_obj(const std::filesystem::path& path) {
  detail::Reader r = detail::Reader::open(path);
  std::vector<double> xyz;
  std::vector<std::vector<int>> faces;
  std::vector<std::int64_t> face_line;
  while (!r.at_end()) {
    const std::int64_t line = r.line();
    detail::Reader rec(r.name(), std::string(r.rest_of_line()));
    const std::string_view key = rec.token('#');
    auto fail = [&](const std::string& what) { throw ParseError(r.name(), line, what); };
    if (key == "v") {
      for (int c = 0; c < 3; ++c) {
        const std::string_view t = rec.token('#');
        double v = 0.0;
        const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
        if (t.empty() || ec != std::errc() || p != t.data() + t.size())
          fail("vertex needs three numeric coordinates, found '" + std::string(t) + "'");
        xyz.push_back(v);
      }
    } else if (key == "f") {
      std::vector<int> f;
      for (std::string_view t = rec.token('#'); !t.empty(); t = rec.token('#')) {
        const std::string_view first = t.substr(0, t.find('/'));
        long long idx = 0;
        const auto [p, ec] = std::from_chars(first.data(), first.data() + first.size(), idx);
        if (first.empty() || ec != std::errc() || p != first.data() + first.size() || idx == 0)
          fail("invalid face vertex '" + std::string(t) + "'");
        const long long nv = static_cast<long long>(xyz.size() / 3);
        const long long i = idx > 0 ? idx - 1 : nv + idx;
        if (i < 0 || i >= nv) fail("face refers to vertex " + std::to_string(idx) + ", which is not defined yet");
        f.push_back(static_cast<int>(i));
      }
      if (f.size() != 3 && f.size() != 4)
        fail("face with " + std::to_string(f.size()) + " vertices (hooke reads triangles and quads)");
      faces.push_back(std::move(f));
      face_line.push_back(line);
    }
  }
  detail::RawElements raw;
  for (size_t k = 0; k < faces.size(); ++k) {
    const std::vector<int>& f = faces[k];
    const mesh::ElementOrigin o{static_cast<std::int64_t>(k) + 1, face_line[k]};
    if (f.size() == 3)
      raw.add_triangle({f[0], f[1], f[2]}, 0, o);
    else
      raw.add_quad({f[0], f[1], f[2], f[3]}, 0, o);
  }
  RowMatX nodes(static_cast<Eigen::Index>(xyz.size() / 3), 3);
  for (Eigen::Index i = 0; i < nodes.size(); ++i) nodes.data()[i] = xyz[static_cast<size_t>(i)];
  return detail::assemble(r.name(), nodes, std::move(raw));
}

void write_obj(const std::filesystem::path& path, const mesh::Mesh& m) {
  if (m.kind == mesh::ElementKind::kTet) throw InvalidArgument("OBJ holds surfaces; write a tet mesh as .msh or .vtu");
  write_file_atomically(path, [&](std::ostream& out) {
    out << "# written by hooke\n" << std::setprecision(17);
    for (int i = 0; i < m.node_count(); ++i)
      out << "v " << m.nodes(i, 0) << ' ' << m.nodes(i, 1) << ' ' << (m.dim() == 3 ? m.nodes(i, 2) : 0.0) << '\n';
    for (int e = 0; e < m.element_count(); ++e) {
      out << 'f';
      for (Eigen::Index k = 0; k < m.elements.cols(); ++k) out << ' ' << m.elements(e, k) + 1;
      out << '\n';
    }
  });
}

}  // namespace hooke::io
