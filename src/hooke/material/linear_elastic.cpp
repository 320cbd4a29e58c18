#include <hooke/material/linear_elastic.hpp>

namespace hooke::material {

Mat3 elasticity_matrix_2d(const Material& m) {
  const double e = m.youngs_modulus, nu = m.poisson_ratio;
  Mat3 d = Mat3::Zero();
  if (m.plane == Plane::kStress) {
    const double c = e / (1.0 - nu * nu);
    d << c, c * nu, 0.0, c * nu, c, 0.0, 0.0, 0.0, c * (1.0 - nu) / 2.0;
  } else {
    const double c = e / ((1.0 + nu) * (1.0 - 2.0 * nu));
    d << c * (1.0 - nu), c * nu, 0.0, c * nu, c * (1.0 - nu), 0.0, 0.0, 0.0, c * (1.0 - 2.0 * nu) / 2.0;
  }
  return d;
}

Mat6 elasticity_matrix_3d(const Material& m) {
  const Lame l = lame(m.youngs_modulus, m.poisson_ratio);
  Mat6 d = Mat6::Zero();
  d.topLeftCorner<3, 3>().setConstant(l.lambda);
  d.topLeftCorner<3, 3>().diagonal().array() += 2.0 * l.mu;
  d.bottomRightCorner<3, 3>().diagonal().setConstant(l.mu);
  return d;
}

}  // namespace hooke::material
