// The large-strain term laws (docs/methods/large_strain.md): the scalar law, Seth-Hill volume and area terms against
// finite differences (the springs' check is in test_spring_block.cpp), their stiffness at rest against the Hookean
// terms, and a single tet's energy under a homogeneous deformation against its closed form from the deformation
// gradient.
#include <gtest/gtest.h>

#include <cmath>
#include <hooke/springs/detail/seth_hill.hpp>
#include <hooke/springs/spring_block.hpp>
#include <hooke/springs/tet_volume_block.hpp>
#include <hooke/springs/triangle_area_block.hpp>
#include <random>
#include <support/block_checks.hpp>

namespace hooke::springs {
namespace {

// A positive tet's corners perturbed by `amount` (m), flat.
VecX perturbed_tet(double amount, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  VecX x(12);
  x << 0, 0, 0, 0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.01;
  for (Eigen::Index i = 0; i < x.size(); ++i) x(i) += amount * u(rng);
  return x;
}

TEST(SethHill, TheScalarLawMatchesItsFiniteDifferencesAndIsHookeanAtRest) {
  for (double q : {-2.0, -1.0, -0.5, 0.0, 0.5, 1.0, 2.0}) {
    const detail::SethHillEnergy rest = detail::seth_hill_energy(1.0, q);
    EXPECT_EQ(rest.value, 0.0);
    EXPECT_NEAR(rest.first, 0.0, 1e-15);
    EXPECT_NEAR(rest.second, 1.0, 1e-14) << q;
    for (double r : {0.35, 0.6, 0.9, 1.3, 1.8}) {
      const double h = 1e-6;
      const detail::SethHillEnergy g = detail::seth_hill_energy(r, q);
      const double d1 = (detail::seth_hill_energy(r + h, q).value - detail::seth_hill_energy(r - h, q).value) / (2 * h);
      const double d2 = (detail::seth_hill_energy(r + h, q).first - detail::seth_hill_energy(r - h, q).first) / (2 * h);
      EXPECT_NEAR(g.first, d1, 1e-7 * (1 + std::abs(d1))) << "q " << q << " r " << r;
      EXPECT_NEAR(g.second, d2, 1e-7 * (1 + std::abs(d2))) << "q " << q << " r " << r;
      // Against the closed forms: e = (r^q - 1)/q, e_0 = ln r.
      const double e = q == 0.0 ? std::log(r) : (std::pow(r, q) - 1.0) / q;
      EXPECT_NEAR(g.value, 0.5 * e * e, 1e-14);
    }
  }
  // The barrier: q <= 0 grows without bound towards r = 0, r <= 0 is inadmissible for q != 1.
  EXPECT_GT(detail::seth_hill_energy(1e-8, 0.0).value, 100.0);
  EXPECT_GT(detail::seth_hill_energy(1e-3, -1.0).value, 1e5);
  EXPECT_TRUE(std::isinf(detail::seth_hill_energy(-0.1, -1.0).value));
  EXPECT_TRUE(std::isinf(detail::seth_hill_energy(0.0, 0.5).value));
}

// The fast powers of the fitted laws' exponents (multiples of 1/8) against std::pow.
TEST(SethHill, RatioPowerIsStdPow) {
  for (double q = -8.0; q <= 8.0; q += 0.125)
    for (double r : {0.05, 0.4, 0.99, 1.0, 1.7, 6.0})
      EXPECT_NEAR(detail::ratio_power(r, q), std::pow(r, q), 1e-14 * std::pow(r, q)) << r << "^" << q;
  EXPECT_NEAR(detail::ratio_power(1.3, 0.3), std::pow(1.3, 0.3), 1e-15);
  EXPECT_EQ(detail::integer_power(2.0, -3), 0.125);
}

TEST(SethHill, SingleSpringFunctionsAgreeWithTheBlockAndWithHookeAtRest) {
  const Vec3 pi(0.01, 0.02, -0.01), pj(-0.005, 0.0, 0.004);
  for (double m : {-1.0, 0.0, 0.5}) {
    const SpringBlock b(3, {{0, 1}}, VecX::Constant(1, 40.0), VecX::Constant(1, 0.02), m);
    VecX x(6);
    x << pi, pj;
    EXPECT_NEAR(seth_hill_spring_energy(pi, pj, 40.0, 0.02, m), b.energy(x), 1e-18);
    const VecX g = test::block_gradient(b, x);
    EXPECT_LT((seth_hill_spring_energy_gradient(pi, pj, 40.0, 0.02, m) - g.head<3>()).norm(), 1e-14);
    EXPECT_LT(
        (seth_hill_spring_energy_hessian(pi, pj, 40.0, 0.02, m) - test::block_hessian(b, 3, x).topLeftCorner(3, 3))
            .norm(),
        1e-11);
    // At rest every law has Lloyd Eq. 6's Hessian.
    const double l0 = (pi - pj).norm();
    EXPECT_LT((seth_hill_spring_energy_hessian(pi, pj, 40.0, l0, m) - spring_energy_hessian(pi, pj, 40.0, l0)).norm(),
              1e-10 * 40.0 / (l0 * l0));
  }
  // m = 1 is the Hookean spring.
  EXPECT_NEAR(seth_hill_spring_energy(pi, pj, 40.0, 0.02, 1.0), spring_energy(pi, pj, 40.0, 0.02), 1e-18);
}

TEST(SethHill, VolumeAndAreaTermsMatchFiniteDifferences) {
  RowMatXi tet(1, 4);
  tet << 0, 1, 2, 3;
  const double v0 = 1e-6 / 6.0;
  for (double q : {-2.0, -1.0, 0.0, 0.5}) {
    for (double v_scale : {0.7, 1.0, 1.4}) {
      const TetVolumeBlock b(tet, VecX::Constant(1, 30.0), VecX::Constant(1, v0 * v_scale), q);
      test::expect_derivatives_match_finite_differences(b, 3, perturbed_tet(0.002, 7), 1e-9, 1e-5);
    }
  }
  RowMatXi tri(1, 3);
  tri << 0, 1, 2;
  VecX x(6);
  x << 0, 0, 0.012, 0.001, -0.002, 0.009;
  for (double q : {-1.0, 0.0}) {
    const TriangleAreaBlock b(tri, VecX::Constant(1, 5.0), VecX::Constant(1, 5e-5 * 1.3), q);
    test::expect_derivatives_match_finite_differences(b, 2, x, 1e-9, 1e-5);
  }
}

TEST(SethHill, ANegativeVolumeStiffnessKeepsTheQuadraticLaw) {
  RowMatXi tet(1, 4);
  tet << 0, 1, 2, 3;
  const VecX x = perturbed_tet(0.002, 11);
  const TetVolumeBlock barrier(tet, VecX::Constant(1, -30.0), VecX::Constant(1, 1e-6 / 6.0), -1.0);
  const TetVolumeBlock quadratic(tet, VecX::Constant(1, -30.0), VecX::Constant(1, 1e-6 / 6.0), 1.0);
  EXPECT_DOUBLE_EQ(barrier.energy(x), quadratic.energy(x));
}

// A tet's springs and volume term under a homogeneous deformation F: the energy is a function of F alone,
// sum_e k_e l0_e^2 g_m(|F d_e| / l0_e) + k_V g_q(det F), written here from F without the blocks' geometry.
TEST(SethHill, ATetsEnergyUnderHomogeneousStretchIsItsClosedForm) {
  Eigen::Matrix<double, 4, 3, Eigen::RowMajor> p;
  p << 0, 0, 0, 0.012, 0.001, 0, 0.002, 0.011, 0, 0.001, 0.002, 0.013;
  std::vector<std::array<int, 2>> pairs{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  VecX k(6), l0(6);
  for (int s = 0; s < 6; ++s) {
    k(s) = 100.0 + 20.0 * s;
    l0(s) = (p.row(pairs[s][0]) - p.row(pairs[s][1])).norm();
  }
  RowMatXi tet(1, 4);
  tet << 0, 1, 2, 3;
  const double v0 = (p.row(1) - p.row(0)).dot((p.row(2) - p.row(0)).cross(p.row(3) - p.row(0))) / 6.0;
  const double kv = 0.05, m = 0.0, q = -1.0;
  const SpringBlock springs(3, pairs, k, l0, m);
  const TetVolumeBlock volume(tet, VecX::Constant(1, kv), VecX::Constant(1, v0), q);
  // Uniaxial stretch and compression along z, lateral contraction by a Poisson-like factor.
  for (double stretch : {0.6, 0.8, 1.2, 1.5}) {
    const double lateral = std::pow(stretch, -0.45);
    const Mat3 f = Vec3(lateral, lateral, stretch).asDiagonal();
    VecX x(12);
    for (int a = 0; a < 4; ++a) x.segment<3>(3 * a) = f * p.row(a).transpose();
    double closed = 0.0;
    for (int s = 0; s < 6; ++s) {
      const Vec3 d = (p.row(pairs[s][0]) - p.row(pairs[s][1])).transpose();
      const double r = (f * d).norm() / d.norm();
      closed += k(s) * l0(s) * l0(s) * 0.5 * std::log(r) * std::log(r);  // m = 0
    }
    const double j = f.determinant();
    closed += kv * 0.5 * (1.0 / j - 1.0) * (1.0 / j - 1.0);  // q = -1: e = (J^-1 - 1) / -1
    EXPECT_NEAR(springs.energy(x) + volume.energy(x), closed, 1e-12 * closed) << "stretch " << stretch;
  }
  // Flattening the tet costs unbounded energy: the press cannot invert it.
  double last = 0.0;
  for (double stretch : {0.3, 0.1, 0.01, 0.001}) {
    const Mat3 f = Vec3(1.0, 1.0, stretch).asDiagonal();
    VecX x(12);
    for (int a = 0; a < 4; ++a) x.segment<3>(3 * a) = f * p.row(a).transpose();
    const double e = volume.energy(x);
    EXPECT_GT(e, last);
    last = e;
  }
  EXPECT_GT(last, 1e4 * kv);
}

}  // namespace
}  // namespace hooke::springs
