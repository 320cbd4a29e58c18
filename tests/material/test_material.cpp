#include <gtest/gtest.h>

#include <hooke/core/error.hpp>
#include <hooke/material/linear_elastic.hpp>
#include <hooke/material/material.hpp>
#include <limits>

namespace hooke::material {
namespace {

TEST(MaterialValidate, RejectsOutOfRangeParameters) {
  Material ok{Law::kLinear, 1000.0, 0.3};
  EXPECT_NO_THROW(validate(ok));
  for (double nu : {0.5, 0.6, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
    Material bad = ok;
    bad.poisson_ratio = nu;
    EXPECT_THROW(validate(bad), InvalidMaterial) << nu;
  }
  Material bad_e = ok;
  bad_e.youngs_modulus = 0.0;
  EXPECT_THROW(validate(bad_e), InvalidMaterial);
  Material bad_t = ok;
  bad_t.thickness = -1.0;
  EXPECT_THROW(validate(bad_t), InvalidMaterial);
}

TEST(MaterialValidate, MessageNamesTheIncompressibleLimit) {
  try {
    validate(Material{Law::kLinear, 1000.0, 0.5});
    FAIL();
  } catch (const InvalidMaterial& e) {
    EXPECT_NE(std::string(e.what()).find("incompressible"), std::string::npos);
  }
}

TEST(LinearElastic, PlaneStressMatrixInvertsToCompliance) {
  // Plane stress: eps_xx = (sigma_xx - nu sigma_yy)/E, gamma = 2 (1 + nu) tau / E.
  const Material m{Law::kLinear, 200.0, 0.25};
  const Mat3 c = elasticity_matrix_2d(m).inverse();
  EXPECT_NEAR(c(0, 0), 1.0 / 200.0, 1e-15);
  EXPECT_NEAR(c(0, 1), -0.25 / 200.0, 1e-15);
  EXPECT_NEAR(c(2, 2), 2.0 * 1.25 / 200.0, 1e-15);
}

TEST(LinearElastic, ThreeDMatrixInvertsToCompliance) {
  const Material m{Law::kLinear, 300.0, 0.3};
  const Mat6 c = elasticity_matrix_3d(m).inverse();
  EXPECT_NEAR(c(0, 0), 1.0 / 300.0, 1e-14);
  EXPECT_NEAR(c(0, 2), -0.3 / 300.0, 1e-14);
  EXPECT_NEAR(c(4, 4), 2.6 / 300.0, 1e-14);
}

TEST(LinearElastic, PlaneStrainMatchesThreeDWithZeroOutOfPlaneStrain) {
  const Material m{Law::kLinear, 300.0, 0.3, Plane::kStrain};
  const Mat6 d3 = elasticity_matrix_3d(m);
  const Mat3 d2 = elasticity_matrix_2d(m);
  EXPECT_NEAR(d2(0, 0), d3(0, 0), 1e-12);
  EXPECT_NEAR(d2(0, 1), d3(0, 1), 1e-12);
  EXPECT_NEAR(d2(2, 2), d3(3, 3), 1e-12);
}

}  // namespace
}  // namespace hooke::material
