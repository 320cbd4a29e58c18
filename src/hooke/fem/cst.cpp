#include <hooke/core/error.hpp>
#include <hooke/fem/cst.hpp>
#include <hooke/material/linear_elastic.hpp>

namespace hooke::fem {

Mat6 cst_stiffness(const Eigen::Matrix<double, 3, 2>& p, const material::Material& material) {
  const double area = 0.5 * ((p(1, 0) - p(0, 0)) * (p(2, 1) - p(0, 1)) - (p(2, 0) - p(0, 0)) * (p(1, 1) - p(0, 1)));
  if (!(area > 0.0)) throw InvalidMesh("cst_stiffness: triangle is clockwise or degenerate");
  const Mat3 d = material::elasticity_matrix_2d(material);
  Eigen::Vector3d beta, gamma;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    beta(i) = p(j, 1) - p(k, 1);
    gamma(i) = p(k, 0) - p(j, 0);
  }
  const double c = material.thickness / (4.0 * area);
  Mat6 kmat;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      kmat(2 * i, 2 * k) = c * (beta(i) * beta(k) * d(0, 0) + gamma(i) * gamma(k) * d(2, 2));
      kmat(2 * i, 2 * k + 1) = c * (beta(i) * gamma(k) * d(0, 1) + gamma(i) * beta(k) * d(2, 2));
      kmat(2 * i + 1, 2 * k) = c * (gamma(i) * beta(k) * d(0, 1) + beta(i) * gamma(k) * d(2, 2));
      kmat(2 * i + 1, 2 * k + 1) = c * (gamma(i) * gamma(k) * d(1, 1) + beta(i) * beta(k) * d(2, 2));
    }
  return kmat;
}

}  // namespace hooke::fem
