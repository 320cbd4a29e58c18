#include <hooke/core/error.hpp>
#include <hooke/io/detail/assemble.hpp>

namespace hooke::io::detail {
namespace {

template <size_t K>
RowMatXi rows_of(const std::vector<std::array<int, K>>& v) {
  RowMatXi m(static_cast<Eigen::Index>(v.size()), static_cast<Eigen::Index>(K));
  for (size_t i = 0; i < v.size(); ++i)
    for (size_t k = 0; k < K; ++k) m(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = v[i][k];
  return m;
}

Eigen::VectorXi regions_of(const std::vector<int>& r, size_t n) {
  Eigen::VectorXi v = Eigen::VectorXi::Zero(static_cast<Eigen::Index>(n));
  for (size_t i = 0; i < r.size() && i < n; ++i) v(static_cast<Eigen::Index>(i)) = r[i];
  return v;
}

}  // namespace

mesh::Mesh assemble(const std::string& source, const RowMatX& nodes, RawElements raw) {
  using mesh::ElementKind;
  mesh::Mesh m;
  m.source = source;
  if (!raw.tets.empty()) {
    m.kind = ElementKind::kTet;
    m.nodes = nodes;
    m.elements = rows_of(raw.tets);
    m.region = regions_of(raw.tet_region, raw.tets.size());
    if (raw.tet_origin.size() == raw.tets.size()) m.origin = std::move(raw.tet_origin);
    return m;
  }
  if (raw.triangles.empty() && raw.quads.empty())
    throw InvalidMesh(source + " holds no triangles, quadrilaterals or tetrahedra");
  const bool planar = nodes.rows() == 0 || nodes.col(2).cwiseAbs().maxCoeff() == 0.0;
  if (planar) {
    if (!raw.triangles.empty() && !raw.quads.empty())
      throw InvalidMesh(source + " mixes triangles and quadrilaterals; hooke meshes hold one element kind");
    m.nodes = nodes.leftCols(2);
    if (!raw.quads.empty()) {
      m.kind = ElementKind::kQuad;
      m.elements = rows_of(raw.quads);
      m.region = regions_of(raw.quad_region, raw.quads.size());
      if (raw.quad_origin.size() == raw.quads.size()) m.origin = std::move(raw.quad_origin);
    } else {
      m.kind = ElementKind::kTriangle;
      m.elements = rows_of(raw.triangles);
      m.region = regions_of(raw.triangle_region, raw.triangles.size());
      if (raw.triangle_origin.size() == raw.triangles.size()) m.origin = std::move(raw.triangle_origin);
    }
    return m;
  }
  if (!raw.quads.empty())
    throw InvalidMesh(source + " is a 3D surface with quadrilaterals; only triangle surfaces are supported");
  m.kind = ElementKind::kSurfaceTriangle;
  m.nodes = nodes;
  m.elements = rows_of(raw.triangles);
  m.region = regions_of(raw.triangle_region, raw.triangles.size());
  if (raw.triangle_origin.size() == raw.triangles.size()) m.origin = std::move(raw.triangle_origin);
  return m;
}

}  // namespace hooke::io::detail
