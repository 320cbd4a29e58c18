#include <algorithm>
#include <cctype>
#include <cmath>
#include <hooke/core/atomic_file.hpp>
#include <hooke/core/output_transaction.hpp>
#include <hooke/io/detail/assemble.hpp>
#include <hooke/io/detail/extension.hpp>
#include <hooke/io/detail/reader.hpp>
#include <hooke/io/tetgen.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/mesh/topology.hpp>
#include <iomanip>
#include <limits>

namespace hooke::io {
namespace {

using detail::Reader;

// The sibling file with extension `ext` (lower case), in upper case when `p`'s own extension is (MESH.NODE beside
// MESH.ELE).
std::filesystem::path with_ext(std::filesystem::path p, const char* ext) {
  const std::string own = p.extension().string();
  const bool upper = own.size() > 1 && std::all_of(own.begin() + 1, own.end(), [](char c) {
                       return std::isupper(static_cast<unsigned char>(c)) != 0;
                     });
  std::string e = ext;
  if (upper)
    for (char& c : e) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return p.replace_extension(e);
}

struct NodeFile {
  RowMatX nodes;
  int base = 1;
};

NodeFile read_node_file(const std::filesystem::path& path) {
  Reader r = Reader::open(path);
  const std::int64_t n = r.integer("the number of points", '#');
  const std::int64_t dim = r.integer("the dimension", '#');
  const std::int64_t nattr = r.integer("the number of attributes", '#');
  const std::int64_t markers = r.integer("the boundary-marker flag", '#');
  if (n < 0) r.fail("negative number of points");
  if (dim != 3 && dim != 2) r.fail("dimension must be 2 or 3, found " + std::to_string(dim));
  // A point is at least its index and dim coordinates, 2 bytes each ("1 0 0 0\n"), checked before allocating.
  r.bounded_count(static_cast<std::uint64_t>(n), static_cast<size_t>(2 * (1 + dim)), "the number of points");
  NodeFile nf;
  nf.nodes = RowMatX::Zero(n, 3);
  for (std::int64_t i = 0; i < n; ++i) {
    const std::int64_t idx = r.integer("a point index", '#');
    if (i == 0) nf.base = static_cast<int>(idx);
    if (idx != i + nf.base) r.fail("point index " + std::to_string(idx) + " out of sequence");
    for (int c = 0; c < dim; ++c) nf.nodes(i, c) = r.number("a coordinate", '#');
    for (std::int64_t a = 0; a < nattr + (markers ? 1 : 0); ++a) r.number("a point attribute or marker", '#');
  }
  if (nf.base != 0 && nf.base != 1) r.fail("point indices must start at 0 or 1");
  return nf;
}

template <size_t K>
std::array<int, K> indices(Reader& r, int base, Eigen::Index nv) {
  std::array<int, K> v{};
  for (size_t k = 0; k < K; ++k) {
    const std::int64_t i = r.integer("a node index", '#') - base;
    if (i < 0 || i >= nv) r.fail("node index " + std::to_string(i + base) + " is out of range");
    v[k] = static_cast<int>(i);
  }
  return v;
}

// A region attribute or boundary marker as an int tag; a ParseError when it is not a whole number in int's range
// (casting it unchecked is undefined behaviour).
int region_tag(const Reader& r, double v) {
  if (!(v >= std::numeric_limits<int>::min() && v <= std::numeric_limits<int>::max()) || v != std::floor(v))
    r.fail("region attribute or marker " + std::to_string(v) + " is not a whole number in the range of int");
  return static_cast<int>(v);
}

}  // namespace

mesh::Mesh read_tetgen(const std::filesystem::path& path) {
  const NodeFile nf = read_node_file(with_ext(path, ".node"));
  detail::RawElements raw;
  std::filesystem::path source;
  if (detail::lower_extension(path) == ".face") {
    source = path;
    Reader r = Reader::open(path);
    const std::int64_t n = r.integer("the number of faces", '#');
    const std::int64_t markers = r.integer("the boundary-marker flag", '#');
    if (n < 0) r.fail("negative number of faces");
    r.bounded_count(static_cast<std::uint64_t>(n), 8, "the number of faces");  // "1 1 2 3\n"
    for (std::int64_t f = 0; f < n; ++f) {
      const std::int64_t number = r.integer("a face index", '#');
      const mesh::ElementOrigin o{number, r.line()};
      const std::array<int, 3> v = indices<3>(r, nf.base, nf.nodes.rows());
      raw.add_triangle(v, markers ? region_tag(r, static_cast<double>(r.integer("a face marker", '#'))) : 0, o);
    }
  } else {
    source = with_ext(path, ".ele");
    Reader r = Reader::open(source);
    const std::int64_t n = r.integer("the number of tetrahedra", '#');
    const std::int64_t npt = r.integer("nodes per tetrahedron", '#');
    const std::int64_t nattr = r.integer("the number of attributes", '#');
    if (npt != 4) r.fail("only 4-node tetrahedra are supported, found " + std::to_string(npt) + " nodes per tet");
    if (n < 0) r.fail("negative number of tetrahedra");
    r.bounded_count(static_cast<std::uint64_t>(n), 10, "the number of tetrahedra");  // "1 1 2 3 4\n"
    for (std::int64_t t = 0; t < n; ++t) {
      const std::int64_t number = r.integer("a tetrahedron index", '#');
      const mesh::ElementOrigin o{number, r.line()};
      const std::array<int, 4> v = indices<4>(r, nf.base, nf.nodes.rows());
      int region = 0;
      for (std::int64_t a = 0; a < nattr; ++a) {
        const double attribute = r.number("a tetrahedron attribute", '#');
        if (a == 0) region = region_tag(r, attribute);
      }
      raw.add_tet(v, region, o);
    }
  }
  mesh::Mesh m = detail::assemble(source.string(), nf.nodes, std::move(raw));
  if (m.kind == mesh::ElementKind::kTet) {
    bool all_negative = m.element_count() > 0;
    for (int e = 0; e < m.element_count() && all_negative; ++e) all_negative = mesh::element_measure(m, e) < 0.0;
    if (all_negative)
      for (int e = 0; e < m.element_count(); ++e) std::swap(m.elements(e, 1), m.elements(e, 2));
  }
  return m;
}

void write_tetgen(const std::filesystem::path& target, const mesh::Mesh& m) {
  if (m.kind == mesh::ElementKind::kQuad) throw InvalidArgument("TetGen files hold tets or triangles, not quads");
  // The .node, .face and .ele files as one transaction: all staged under one stem, then renamed with the
  // .ele (what a reader opens) last; a failure leaves the previous files untouched.
  OutputTransaction outputs;
  for (const char* ext : {".node", ".face"}) outputs.stage_file(with_ext(target, ext));
  const std::filesystem::path path = outputs.stage_file(with_ext(target, ".ele"));
  const int nv = m.node_count();
  write_file_atomically(with_ext(path, ".node"), [&](std::ostream& out) {
    out << std::setprecision(17) << nv << " 3 0 0\n";
    for (int i = 0; i < nv; ++i)
      out << i + 1 << ' ' << m.nodes(i, 0) << ' ' << m.nodes(i, 1) << ' ' << (m.dim() == 3 ? m.nodes(i, 2) : 0.0)
          << '\n';
  });
  auto write_faces = [&](const RowMatXi& faces) {
    write_file_atomically(with_ext(path, ".face"), [&](std::ostream& out) {
      out << faces.rows() << " 0\n";
      for (Eigen::Index f = 0; f < faces.rows(); ++f)
        out << f + 1 << ' ' << faces(f, 0) + 1 << ' ' << faces(f, 1) + 1 << ' ' << faces(f, 2) + 1 << '\n';
    });
  };
  if (m.kind == mesh::ElementKind::kTet) {
    write_file_atomically(with_ext(path, ".ele"), [&](std::ostream& out) {
      out << m.element_count() << " 4 1\n";
      for (int e = 0; e < m.element_count(); ++e) {
        out << e + 1;
        for (int k = 0; k < 4; ++k) out << ' ' << m.elements(e, k) + 1;
        out << ' ' << (m.region.size() == m.element_count() ? m.region(e) : 0) << '\n';
      }
    });
    write_faces(mesh::boundary_facets(m));
  } else if (m.kind == mesh::ElementKind::kSurfaceTriangle || m.kind == mesh::ElementKind::kTriangle) {
    write_faces(m.elements);
  }
  outputs.commit();
}

}  // namespace hooke::io
