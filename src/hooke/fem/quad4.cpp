#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/fem/quad4.hpp>
#include <hooke/material/linear_elastic.hpp>

namespace hooke::fem {

double quad4_gradients(const Eigen::Matrix<double, 4, 2>& nodes, double xi, double eta,
                       Eigen::Matrix<double, 4, 2>& gradients) {
  static constexpr double kXi[4] = {-1.0, 1.0, 1.0, -1.0};
  static constexpr double kEta[4] = {-1.0, -1.0, 1.0, 1.0};
  Eigen::Matrix<double, 4, 2> dn_dref;
  for (int a = 0; a < 4; ++a) {
    dn_dref(a, 0) = 0.25 * kXi[a] * (1.0 + kEta[a] * eta);
    dn_dref(a, 1) = 0.25 * kEta[a] * (1.0 + kXi[a] * xi);
  }
  const Mat2 jac = nodes.transpose() * dn_dref;  // dX/dref
  const double det = jac.determinant();
  gradients = dn_dref * jac.inverse();
  return det;
}

Mat8 quad4_stiffness(const Eigen::Matrix<double, 4, 2>& nodes, const material::Material& material) {
  const Mat3 d = material::elasticity_matrix_2d(material);
  const double g = 1.0 / std::sqrt(3.0);
  Mat8 k = Mat8::Zero();
  for (double xi : {-g, g})
    for (double eta : {-g, g}) {
      Eigen::Matrix<double, 4, 2> dn;
      const double det = quad4_gradients(nodes, xi, eta, dn);
      if (!(det > 0.0)) throw InvalidMesh("quad4_stiffness: Jacobian not positive (clockwise or non-convex quad)");
      Eigen::Matrix<double, 3, 8> b = Eigen::Matrix<double, 3, 8>::Zero();
      for (int a = 0; a < 4; ++a) {
        b(0, 2 * a) = dn(a, 0);
        b(1, 2 * a + 1) = dn(a, 1);
        b(2, 2 * a) = dn(a, 1);
        b(2, 2 * a + 1) = dn(a, 0);
      }
      k += material.thickness * det * b.transpose() * d * b;  // Gauss weights are 1
    }
  return k;
}

}  // namespace hooke::fem
