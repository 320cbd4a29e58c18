#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/topology.hpp>
#include <hooke/mesh/validate.hpp>
#include <random>
#include <support/meshes.hpp>

namespace hooke::test {

mesh::Mesh perturb_interior(mesh::Mesh m, double fraction, unsigned seed) {
  double min_edge = std::numeric_limits<double>::infinity();
  for (const auto& e : mesh::unique_edges(m))
    min_edge = std::min(min_edge, (m.nodes.row(e[0]) - m.nodes.row(e[1])).norm());
  const Eigen::RowVectorXd lo = m.nodes.colwise().minCoeff(), hi = m.nodes.colwise().maxCoeff();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double tol = 1e-9 * (hi - lo).norm();
  for (int i = 0; i < m.node_count(); ++i) {
    bool boundary = false;
    for (int c = 0; c < m.dim(); ++c)
      boundary = boundary || m.nodes(i, c) <= lo(c) + tol || m.nodes(i, c) >= hi(c) - tol;
    if (boundary) continue;
    for (int c = 0; c < m.dim(); ++c) m.nodes(i, c) += fraction * min_edge * u(rng);
  }
  mesh::validate(m);
  return m;
}

mesh::Mesh irregular_mesh(mesh::ElementKind kind, int cells, double fraction) {
  const double h = 0.005;
  switch (kind) {
    case mesh::ElementKind::kTriangle:
      return perturb_interior(mesh::rectangle_triangles(h * cells, h * (cells + 1), cells, cells + 1), fraction);
    case mesh::ElementKind::kQuad:
      return perturb_interior(mesh::rectangle_quads(h * cells, h * (cells + 1), cells, cells + 1), fraction);
    default: {
      const int n = std::max(2, 2 * cells / 3);
      return perturb_interior(mesh::tet_box(h * n, h * n, h * (n + 1), n, n, n + 1), fraction);
    }
  }
}

VecX flat_positions(const mesh::Mesh& m) { return mesh::flat_positions(m); }

Mat3 random_rotation(unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n;
  Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  return q.normalized().toRotationMatrix();
}

mesh::Mesh two_pieces(const mesh::Mesh& a, const mesh::Mesh& b, const std::string& source) {
  RowMatX x(a.node_count() + b.node_count(), 3);
  x << a.nodes, b.nodes;
  RowMatXi t(a.element_count() + b.element_count(), 3);
  t << a.elements, (b.elements.array() + a.node_count()).matrix();
  return mesh::make_mesh(mesh::ElementKind::kSurfaceTriangle, x, t, source);
}

}  // namespace hooke::test
