#include <array>
#include <cstdint>
#include <hooke/core/atomic_file.hpp>
#include <hooke/io/detail/assemble.hpp>
#include <hooke/io/detail/reader.hpp>
#include <hooke/io/stl.hpp>
#include <iomanip>
#include <map>

namespace hooke::io {
namespace {

struct Welder {
  std::map<std::array<double, 3>, int> index;
  std::vector<double> xyz;
  int add(const std::array<double, 3>& p) {
    auto [it, inserted] = index.try_emplace(p, static_cast<int>(xyz.size() / 3));
    if (inserted) xyz.insert(xyz.end(), p.begin(), p.end());
    return it->second;
  }
  RowMatX nodes() const {
    RowMatX n(static_cast<Eigen::Index>(xyz.size() / 3), 3);
    for (Eigen::Index i = 0; i < n.size(); ++i) n.data()[i] = xyz[static_cast<size_t>(i)];
    return n;
  }
};

Vec3 facet_normal(const mesh::Mesh& m, int e) {
  Vec3 p[3];
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) p[k](c) = c < m.dim() ? m.nodes(m.elements(e, k), c) : 0.0;
  const Vec3 n = (p[1] - p[0]).cross(p[2] - p[0]);
  return n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero();
}

}  // namespace

mesh::Mesh read_stl(const std::filesystem::path& path) {
  detail::Reader r = detail::Reader::open(path);
  Welder w;
  detail::RawElements raw;
  const size_t size = r.data().size();
  bool binary = false;
  if (size >= 84) {
    std::uint32_t n = 0;
    std::memcpy(&n, r.data().data() + 80, 4);
    binary = size == 84 + 50 * static_cast<size_t>(n);
  }
  if (binary) {
    r.skip_bytes(80, "the header");
    const auto n = r.binary<std::uint32_t>("the triangle count");
    for (std::uint32_t t = 0; t < n; ++t) {
      r.skip_bytes(12, "a facet normal");
      std::array<int, 3> tri{};
      for (auto& v : tri) {
        std::array<double, 3> p{};
        for (auto& c : p) c = r.binary<float>("a vertex");
        v = w.add(p);
      }
      r.skip_bytes(2, "an attribute count");
      raw.add_triangle(tri, 0, {static_cast<std::int64_t>(t) + 1, 0});
    }
  } else {
    if (r.token() != "solid")
      r.fail("neither a binary STL (size does not match its triangle count) nor an ASCII STL (no 'solid')");
    r.rest_of_line();
    while (true) {
      const std::string_view t = r.expect_token("'facet' or 'endsolid'");
      if (t == "endsolid") break;
      if (t != "facet") r.fail("expected 'facet' or 'endsolid', found '" + std::string(t) + "'");
      const std::int64_t facet_line = r.line();
      r.rest_of_line();  // normal
      if (r.expect_token("'outer loop'") != "outer" || r.expect_token("'outer loop'") != "loop")
        r.fail("expected 'outer loop'");
      std::array<int, 3> tri{};
      for (auto& v : tri) {
        if (r.expect_token("'vertex'") != "vertex") r.fail("expected 'vertex' (STL facets must be triangles)");
        std::array<double, 3> p{};
        for (auto& c : p) c = r.number("a vertex coordinate");
        v = w.add(p);
      }
      if (r.expect_token("'endloop'") != "endloop") r.fail("expected 'endloop' (STL facets must be triangles)");
      if (r.expect_token("'endfacet'") != "endfacet") r.fail("expected 'endfacet'");
      raw.add_triangle(tri, 0, {static_cast<std::int64_t>(raw.triangles.size()) + 1, facet_line});
    }
  }
  return detail::assemble(r.name(), w.nodes(), std::move(raw));
}

void write_stl(const std::filesystem::path& path, const mesh::Mesh& m, bool binary) {
  if (mesh::nodes_per_element(m.kind) != 3 || m.kind == mesh::ElementKind::kTet)
    throw InvalidArgument("STL holds triangles only");
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        auto coord = [&](int node, int c) { return c < m.dim() ? m.nodes(node, c) : 0.0; };
        if (binary) {
          char header[80] = "binary STL written by hooke";
          out.write(header, 80);
          const auto n = static_cast<std::uint32_t>(m.element_count());
          out.write(reinterpret_cast<const char*>(&n), 4);
          for (int e = 0; e < m.element_count(); ++e) {
            const Vec3 nrm = facet_normal(m, e);
            for (int c = 0; c < 3; ++c) {
              const auto f = static_cast<float>(nrm(c));
              out.write(reinterpret_cast<const char*>(&f), 4);
            }
            for (int k = 0; k < 3; ++k)
              for (int c = 0; c < 3; ++c) {
                const auto f = static_cast<float>(coord(m.elements(e, k), c));
                out.write(reinterpret_cast<const char*>(&f), 4);
              }
            const std::uint16_t attr = 0;
            out.write(reinterpret_cast<const char*>(&attr), 2);
          }
        } else {
          out << "solid hooke\n" << std::setprecision(17);
          for (int e = 0; e < m.element_count(); ++e) {
            const Vec3 nrm = facet_normal(m, e);
            out << "  facet normal " << nrm(0) << ' ' << nrm(1) << ' ' << nrm(2) << "\n    outer loop\n";
            for (int k = 0; k < 3; ++k)
              out << "      vertex " << coord(m.elements(e, k), 0) << ' ' << coord(m.elements(e, k), 1) << ' '
                  << coord(m.elements(e, k), 2) << '\n';
            out << "    endloop\n  endfacet\n";
          }
          out << "endsolid hooke\n";
        }
      },
      binary);
}

}  // namespace hooke::io
