#include <hooke/core/atomic_file.hpp>
#include <hooke/io/detail/assemble.hpp>
#include <hooke/io/detail/reader.hpp>
#include <hooke/io/off.hpp>
#include <iomanip>

namespace hooke::io {

mesh::Mesh read_off(const std::filesystem::path& path) {
  detail::Reader r = detail::Reader::open(path);
  const std::string_view header = r.token('#');
  if (header != "OFF")
    r.fail("not an OFF file (expected the header 'OFF', found '" + std::string(header.substr(0, 20)) + "')");
  const std::int64_t nv = r.integer("the vertex count", '#');
  const std::int64_t nf = r.integer("the face count", '#');
  r.integer("the edge count", '#');
  if (nv < 0 || nf < 0) r.fail("negative counts");
  // A vertex takes at least 6 bytes ("0 0 0\n"), a face at least 8 ("3 0 1 2\n"): counts that cannot fit in the
  // file are refused before anything is allocated for them.
  r.bounded_count(static_cast<std::uint64_t>(nv), 6, "the vertex count");
  r.bounded_count(static_cast<std::uint64_t>(nf), 8, "the face count");
  RowMatX nodes(nv, 3);
  for (std::int64_t i = 0; i < nv; ++i)
    for (int c = 0; c < 3; ++c) nodes(i, c) = r.number("a vertex coordinate", '#');
  detail::RawElements raw;
  for (std::int64_t f = 0; f < nf; ++f) {
    const std::int64_t n = r.integer("a face's vertex count", '#');
    if (n != 3 && n != 4) r.fail("face with " + std::to_string(n) + " vertices (hooke reads triangles and quads)");
    std::array<int, 4> v{};
    for (int k = 0; k < n; ++k) {
      const std::int64_t i = r.integer("a vertex index", '#');
      if (i < 0 || i >= nv) r.fail("vertex index " + std::to_string(i) + " is out of range");
      v[static_cast<size_t>(k)] = static_cast<int>(i);
    }
    const mesh::ElementOrigin o{f + 1, r.line()};
    while (!r.at_end_of_line()) r.token('#');  // optional colour
    if (n == 3)
      raw.add_triangle({v[0], v[1], v[2]}, 0, o);
    else
      raw.add_quad(v, 0, o);
  }
  return detail::assemble(r.name(), nodes, std::move(raw));
}

void write_off(const std::filesystem::path& path, const mesh::Mesh& m) {
  if (m.kind == mesh::ElementKind::kTet) throw InvalidArgument("OFF holds surfaces; write a tet mesh as .msh or .vtu");
  write_file_atomically(path, [&](std::ostream& out) {
    out << "OFF\n" << m.node_count() << ' ' << m.element_count() << " 0\n" << std::setprecision(17);
    for (int i = 0; i < m.node_count(); ++i)
      out << m.nodes(i, 0) << ' ' << m.nodes(i, 1) << ' ' << (m.dim() == 3 ? m.nodes(i, 2) : 0.0) << '\n';
    for (int e = 0; e < m.element_count(); ++e) {
      out << m.elements.cols();
      for (Eigen::Index k = 0; k < m.elements.cols(); ++k) out << ' ' << m.elements(e, k);
      out << '\n';
    }
  });
}

}  // namespace hooke::io
