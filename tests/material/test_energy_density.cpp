// P = dpsi/dF and dP/dF checked against central differences for every law, in 2D and 3D.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <hooke/material/energy_density.hpp>
#include <random>

namespace hooke::material {
namespace {

template <int D>
Eigen::Matrix<double, D, D> test_deformation(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.25, 0.25);
  Eigen::Matrix<double, D, D> f = Eigen::Matrix<double, D, D>::Identity();
  for (int i = 0; i < D * D; ++i) f.data()[i] += u(rng);
  return f;
}

class EnergyDensity : public ::testing::TestWithParam<Law> {};

template <int D>
void check_derivatives(Law law) {
  const Lame lame = material::lame(1000.0, 0.3);
  const double h = 1e-6;
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const Eigen::Matrix<double, D, D> f = test_deformation<D>(seed);
    const auto p = first_piola(law, f, lame);
    const auto dp = first_piola_derivative(law, f, lame);
    for (int k = 0; k < D * D; ++k) {
      Eigen::Matrix<double, D, D> fp = f, fm = f;
      fp.data()[k] += h;
      fm.data()[k] -= h;
      const double dpsi = (energy_density(law, fp, lame) - energy_density(law, fm, lame)) / (2 * h);
      EXPECT_NEAR(p.data()[k], dpsi, 1e-6 * std::max(1.0, std::abs(dpsi))) << "P entry " << k;
      const Eigen::Matrix<double, D, D> dp_fd = (first_piola(law, fp, lame) - first_piola(law, fm, lame)) / (2 * h);
      for (int i = 0; i < D * D; ++i)
        EXPECT_NEAR(dp(i, k), dp_fd.data()[i], 1e-5 * std::max(1.0, std::abs(dp_fd.data()[i])));
    }
  }
}

TEST_P(EnergyDensity, StressIsGradientOfEnergy2D) { check_derivatives<2>(GetParam()); }
TEST_P(EnergyDensity, StressIsGradientOfEnergy3D) { check_derivatives<3>(GetParam()); }

TEST_P(EnergyDensity, ZeroAtRestAndStressFree) {
  const Lame lame = material::lame(1000.0, 0.3);
  EXPECT_DOUBLE_EQ(energy_density(GetParam(), Mat3::Identity().eval(), lame), 0.0);
  EXPECT_LT(first_piola(GetParam(), Mat3::Identity().eval(), lame).norm(), 1e-12);
}

TEST_P(EnergyDensity, TangentAtRestIsLinearElasticity) {
  // All three laws share the small-strain limit: dP/dF at F = I equals the linear law's.
  const Lame lame = material::lame(2500.0, 0.28);
  const Mat9 reference = first_piola_derivative(Law::kLinear, Mat3::Identity().eval(), lame);
  EXPECT_LT((first_piola_derivative(GetParam(), Mat3::Identity().eval(), lame) - reference).norm(),
            1e-10 * reference.norm());
}

INSTANTIATE_TEST_SUITE_P(AllLaws, EnergyDensity, ::testing::Values(Law::kLinear, Law::kStVK, Law::kNeoHookean),
                         [](const auto& param_info) { return std::string(law_name(param_info.param)); });

TEST(EnergyDensityNonlinear, RotationInvariant) {
  const Lame lame = material::lame(1000.0, 0.3);
  const Mat3 f = test_deformation<3>(9);
  const Mat3 r = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  for (Law law : {Law::kStVK, Law::kNeoHookean})
    EXPECT_NEAR(energy_density(law, (r * f).eval(), lame), energy_density(law, f, lame), 1e-10);
  // The linear law is not: this is the rotational artefact Lloyd Sec. 5.7 shows on the cone.
  EXPECT_GT(std::abs(energy_density(Law::kLinear, r.eval(), lame)), 1.0);
}

TEST(EnergyDensityNonlinear, NeoHookeanInfiniteWhenInverted) {
  Mat3 f = Mat3::Identity();
  f(2, 2) = -0.5;
  EXPECT_TRUE(std::isinf(energy_density(Law::kNeoHookean, f, material::lame(1000.0, 0.3))));
}

}  // namespace
}  // namespace hooke::material
