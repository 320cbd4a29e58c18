#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/mesh/tet_quality.hpp>
#include <numbers>

namespace hooke::mesh {

double radius_ratio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  const double six_volume = std::abs(u.dot(v.cross(w)));
  // Inradius r = 3 V / (sum of face areas); circumradius R = |u^2 (v x w) + v^2 (w x u) + w^2 (u x v)| / (12 V).
  const double faces = 0.5 * (u.cross(v).norm() + v.cross(w).norm() + w.cross(u).norm() + (c - b).cross(d - b).norm());
  const Vec3 centre = u.squaredNorm() * v.cross(w) + v.squaredNorm() * w.cross(u) + w.squaredNorm() * u.cross(v);
  if (!(six_volume > 0.0) || !(faces > 0.0)) return 0.0;
  const double inradius = six_volume / (2.0 * faces), circumradius = centre.norm() / (2.0 * six_volume);
  return 3.0 * inradius / circumradius;
}

std::array<double, 6> dihedral_angles(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // n[k]: the normal of the face opposite node k, pointing away from node k (outward for either orientation).
  const std::array<Vec3, 4> p{a, b, c, d};
  std::array<Vec3, 4> n;
  for (int k = 0; k < 4; ++k) {
    const Vec3& q0 = p[static_cast<size_t>((k + 1) % 4)];
    const Vec3& q1 = p[static_cast<size_t>((k + 2) % 4)];
    const Vec3& q2 = p[static_cast<size_t>((k + 3) % 4)];
    Vec3 m = (q1 - q0).cross(q2 - q0).normalized();
    if (m.dot(p[static_cast<size_t>(k)] - q0) > 0.0) m = -m;
    n[static_cast<size_t>(k)] = m;
  }
  // The edge ij is where the faces opposite the other two nodes k, l meet: angle = pi - angle(n_k, n_l).
  constexpr std::array<std::array<int, 4>, 6> edges{
      {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}, {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}}};
  std::array<double, 6> angles{};
  for (size_t e = 0; e < 6; ++e) {
    const double cosine =
        std::clamp(n[static_cast<size_t>(edges[e][2])].dot(n[static_cast<size_t>(edges[e][3])]), -1.0, 1.0);
    angles[e] = std::numbers::pi - std::acos(cosine);
  }
  return angles;
}

TetQualityReport tet_quality(const Mesh& mesh, double radius_ratio_floor) {
  if (mesh.kind != ElementKind::kTet || mesh.element_count() == 0)
    throw InvalidArgument("tet_quality needs a mesh of tets" + (mesh.source.empty() ? "" : ", not " + mesh.source));
  TetQualityReport r;
  r.min_radius_ratio = 2.0;
  r.min_dihedral = 180.0;
  double sum = 0.0;
  for (int e = 0; e < mesh.element_count(); ++e) {
    const Vec3 a = mesh.nodes.row(mesh.elements(e, 0)).transpose(), b = mesh.nodes.row(mesh.elements(e, 1)).transpose(),
               c = mesh.nodes.row(mesh.elements(e, 2)).transpose(), d = mesh.nodes.row(mesh.elements(e, 3)).transpose();
    const double rho = radius_ratio(a, b, c, d);
    sum += rho;
    if (rho < r.min_radius_ratio) {
      r.min_radius_ratio = rho;
      r.worst_element = e;
    }
    if (rho < radius_ratio_floor) ++r.below_floor;
    if (rho <= 0.0) {
      r.min_dihedral = 0.0;
      r.max_dihedral = 180.0;
      continue;
    }
    for (const double angle : dihedral_angles(a, b, c, d)) {
      r.min_dihedral = std::min(r.min_dihedral, angle * 180.0 / std::numbers::pi);
      r.max_dihedral = std::max(r.max_dihedral, angle * 180.0 / std::numbers::pi);
    }
  }
  r.mean_radius_ratio = sum / mesh.element_count();
  return r;
}

}  // namespace hooke::mesh
