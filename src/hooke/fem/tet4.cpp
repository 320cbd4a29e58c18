#include <hooke/core/error.hpp>
#include <hooke/fem/tet4.hpp>
#include <hooke/material/linear_elastic.hpp>

namespace hooke::fem {

double tet4_gradients(const Eigen::Matrix<double, 4, 3>& nodes, Eigen::Matrix<double, 4, 3>& gradients) {
  // App. B: (1, x, y, z)^T = C (N1..N4)^T, so N = C^-1 (1, x, y, z)^T and dN_a/dX_c = (C^-1)(a, 1 + c).
  Eigen::Matrix4d c;
  c.row(0).setOnes();
  c.bottomRows<3>() = nodes.transpose();
  const double volume = c.determinant() / 6.0;
  const Eigen::Matrix4d c_inv = c.inverse();
  gradients = c_inv.rightCols<3>();
  return volume;
}

Mat12 tet4_stiffness(const Eigen::Matrix<double, 4, 3>& nodes, const material::Material& material) {
  Eigen::Matrix<double, 4, 3> dn;
  const double volume = tet4_gradients(nodes, dn);
  if (!(volume > 0.0)) throw InvalidMesh("tet4_stiffness: tet has non-positive volume");
  Eigen::Matrix<double, 6, 12> b = Eigen::Matrix<double, 6, 12>::Zero();
  for (int a = 0; a < 4; ++a) {
    const double nx = dn(a, 0), ny = dn(a, 1), nz = dn(a, 2);
    b(0, 3 * a) = nx;
    b(1, 3 * a + 1) = ny;
    b(2, 3 * a + 2) = nz;
    b(3, 3 * a) = ny;  // gamma_xy
    b(3, 3 * a + 1) = nx;
    b(4, 3 * a + 1) = nz;  // gamma_yz
    b(4, 3 * a + 2) = ny;
    b(5, 3 * a) = nz;  // gamma_zx
    b(5, 3 * a + 2) = nx;
  }
  return volume * b.transpose() * material::elasticity_matrix_3d(material) * b;
}

}  // namespace hooke::fem
