#include <hooke/mesh/measure.hpp>

namespace hooke::mesh {

double signed_area(const Vec2& a, const Vec2& b, const Vec2& c) {
  return 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y()));
}

double signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

double element_measure(const Mesh& mesh, int e) {
  const auto& n = mesh.nodes;
  const auto idx = mesh.elements.row(e);
  switch (mesh.kind) {
    case ElementKind::kTriangle:
      return signed_area(n.row(idx(0)).transpose(), n.row(idx(1)).transpose(), n.row(idx(2)).transpose());
    case ElementKind::kQuad: {
      double twice = 0.0;
      for (int k = 0; k < 4; ++k) {
        const int i = idx(k), j = idx((k + 1) % 4);
        twice += n(i, 0) * n(j, 1) - n(j, 0) * n(i, 1);
      }
      return 0.5 * twice;
    }
    case ElementKind::kTet:
      return signed_volume(n.row(idx(0)).transpose(), n.row(idx(1)).transpose(), n.row(idx(2)).transpose(),
                           n.row(idx(3)).transpose());
    case ElementKind::kSurfaceTriangle: {
      const Vec3 a = n.row(idx(0)).transpose(), b = n.row(idx(1)).transpose(), c = n.row(idx(2)).transpose();
      return 0.5 * (b - a).cross(c - a).norm();
    }
  }
  return 0.0;
}

double total_measure(const Mesh& mesh) {
  double sum = 0.0;
  for (int e = 0; e < mesh.element_count(); ++e) sum += element_measure(mesh, e);
  return sum;
}

double bounding_box_diagonal(const Mesh& mesh) {
  if (mesh.nodes.rows() == 0) return 0.0;
  return (mesh.nodes.colwise().maxCoeff() - mesh.nodes.colwise().minCoeff()).norm();
}

}  // namespace hooke::mesh
