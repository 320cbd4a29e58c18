#include <hooke/interactive/picking.hpp>
#include <limits>

namespace hooke::interactive {

std::optional<SurfaceHit> pick_surface(const RowMatX& x, const RowMatXi& triangles, const Vec3& origin,
                                       const Vec3& direction) {
  std::optional<SurfaceHit> best;
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    const Vec3 a = x.row(triangles(f, 0)).transpose(), b = x.row(triangles(f, 1)).transpose(),
               c = x.row(triangles(f, 2)).transpose();
    const Vec3 e1 = b - a, e2 = c - a, p = direction.cross(e2);
    const double det = e1.dot(p);
    if (std::abs(det) < 1e-300) continue;  // the ray lies in the triangle's plane
    const double inv = 1.0 / det;
    const Vec3 t = origin - a;
    const double u = t.dot(p) * inv;
    if (u < 0.0 || u > 1.0) continue;
    const Vec3 q = t.cross(e1);
    const double v = direction.dot(q) * inv;
    if (v < 0.0 || u + v > 1.0) continue;
    const double s = e2.dot(q) * inv;
    if (s <= 0.0 || (best && s >= best->distance)) continue;
    SurfaceHit h;
    h.triangle = static_cast<int>(f);
    h.distance = s;
    h.point = origin + s * direction;
    double nearest = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
      const double dist = (x.row(triangles(f, k)).transpose() - h.point).squaredNorm();
      if (dist < nearest) {
        nearest = dist;
        h.nearest_node = triangles(f, k);
      }
    }
    best = h;
  }
  return best;
}

std::vector<int> nodes_within(const RowMatX& x, const std::vector<int>& candidates, const Vec3& centre, double radius,
                              int nearest) {
  std::vector<int> out{nearest};
  if (radius <= 0.0) return out;
  for (const int i : candidates)
    if (i != nearest && (x.row(i).transpose() - centre).norm() <= radius) out.push_back(i);
  return out;
}

RowMatX positions_3d(const VecX& flat, int dim) {
  const Eigen::Index n = flat.size() / dim;
  RowMatX out = RowMatX::Zero(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    if (dim == 3) {
      out.row(i) = flat.segment(3 * i, 3).transpose();
    } else {
      out(i, 0) = flat(2 * i);
      out(i, 2) = flat(2 * i + 1);
    }
  }
  return out;
}

VecX from_3d(const Vec3& v, int dim) {
  if (dim == 3) return v;
  VecX out(2);
  out << v(0), v(2);
  return out;
}

}  // namespace hooke::interactive
