#pragma once
// Strains of a tet in Mandel notation, eps~ = (eps_xx, eps_yy, eps_zz, sqrt 2 eps_yz, sqrt 2 eps_zx, sqrt 2 eps_xy):
// eps~ . eps~ = eps : eps, so Frobenius norms of 6 x 6 matrices are those of the 4th-order tensors.
#include <Eigen/Core>
#include <cmath>

namespace hooke::calibrate::detail {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

// Mandel vector of n n^T for a unit vector n: n . eps n = mandel_dyad(n) . eps~. A linearised spring of stiffness
// k and length l stores k l^2 (n . eps n)^2 / 2 under a uniform strain: its strain-space Hessian is
// k l^2 mandel_dyad(n) mandel_dyad(n)^T (the rotation part of a displacement does not stretch it).
inline Vec6 mandel_dyad(const Eigen::Vector3d& n) {
  const double r = std::sqrt(2.0);
  Vec6 v;
  v << n.x() * n.x(), n.y() * n.y(), n.z() * n.z(), r * n.y() * n.z(), r * n.z() * n.x(), r * n.x() * n.y();
  return v;
}

// m = (1, 1, 1, 0, 0, 0): tr eps = m . eps~; a volume term k_V (V - V0)^2 / (2 V0^2) stores k_V (m . eps~)^2 / 2.
inline Vec6 mandel_trace() { return (Vec6() << 1, 1, 1, 0, 0, 0).finished(); }

}  // namespace hooke::calibrate::detail
