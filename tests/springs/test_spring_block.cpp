// Spring energy, forces and Hessian against finite differences; Lloyd et al. 2007's exactness claims for the
// equilateral triangle (Eq. 8, nu = 1/3) and the prestrained square (Eq. 10-11, nu = 1/3) as executable checks.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <hooke/core/symmetric_eigen.hpp>
#include <hooke/fem/cst.hpp>
#include <hooke/fem/quad4.hpp>
#include <hooke/springs/spring_block.hpp>
#include <random>
#include <support/block_checks.hpp>

namespace hooke::springs {
namespace {

SparseMatrix hessian(const SpringBlock& b, const VecX& x, bool psd = false) {
  return model::block_hessian(b, b.dim(), x, psd);
}

// Hookean springs (m = 1) and the large-strain Seth-Hill laws (docs/methods/large_strain.md), springs both stretched
// and compressed; the PSD-projected Hessian has no negative eigenvalue.
TEST(SpringBlock, GradientAndHessianMatchFiniteDifferences) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const auto& [dim, m] :
       std::vector<std::pair<int, double>>{{2, 1.0}, {3, 1.0}, {2, -1.0}, {3, 0.0}, {3, 0.5}, {2, 2.0}}) {
    const int n = 6;
    VecX x(dim * n);
    for (Eigen::Index i = 0; i < x.size(); ++i) x(i) = 0.01 * u(rng);
    std::vector<std::array<int, 2>> pairs{{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 0}, {0, 3}};
    VecX k(7), l0(7);
    for (int s = 0; s < 7; ++s) {
      k(s) = 10.0 + 5.0 * s;
      const auto [i, j] = pairs[static_cast<size_t>(s)];
      l0(s) = (x.segment(dim * i, dim) - x.segment(dim * j, dim)).norm() * (s % 2 ? 1.2 : 0.85);  // both signs
    }
    const SpringBlock b(dim, pairs, k, l0, m);
    test::expect_derivatives_match_finite_differences(b, dim, x, 1e-8, 1e-6);
    const VecX eig = symmetric_eigenvalues(MatX(hessian(b, x, true)));
    EXPECT_GT(eig.minCoeff(), -1e-9 * eig.maxCoeff()) << "m " << m;
    EXPECT_EQ(b.central_springs() != nullptr, m == 1.0);  // the local/global split is for Hookean springs only
  }
}

TEST(SpringBlock, SingleSpringFunctionsAgreeWithTheBlock) {
  const Vec3 pi(0.01, 0.02, -0.01), pj(-0.005, 0.0, 0.004);
  const SpringBlock b(3, {{0, 1}}, VecX::Constant(1, 40.0), VecX::Constant(1, 0.02));
  VecX x(6);
  x << pi, pj;
  EXPECT_NEAR(spring_energy(pi, pj, 40.0, 0.02), b.energy(x), 1e-18);
  VecX g = VecX::Zero(6);
  b.add_gradient(x, g);
  EXPECT_LT((spring_energy_gradient(pi, pj, 40.0, 0.02) - g.head<3>()).norm(), 1e-15);
  EXPECT_LT((spring_energy_hessian(pi, pj, 40.0, 0.02) - MatX(hessian(b, x)).topLeftCorner(3, 3)).norm(), 1e-12);
}

TEST(SpringBlock, AtRestTheHessianIsLloydEquation6) {
  const Vec2 pi(0.3, 0.1), pj(-0.2, 0.4);
  const double k = 7.0, l0 = (pi - pj).norm();
  const MatX a = spring_energy_hessian(pi, pj, k, l0);
  EXPECT_LT((a - k / (l0 * l0) * (pi - pj) * (pi - pj).transpose()).norm(), 1e-14);
}

// Lloyd Sec. 3.3: three springs of k = E t sqrt(3)/4 on an equilateral triangle have exactly the CST's
// stiffness matrix when nu = 1/3.
TEST(LloydEquilateral, SpringStiffnessEqualsCstAtNuOneThird) {
  const double e = 14630.0, t = 0.001, edge = 0.01;
  Eigen::Matrix<double, 3, 2> p;
  p << 0.0, 0.0, edge, 0.0, edge / 2, edge * std::sqrt(3.0) / 2;
  const Eigen::Rotation2Dd rot(0.4);
  for (int a = 0; a < 3; ++a) p.row(a) = (rot * p.row(a).transpose()).transpose();
  const double k = e * t * std::sqrt(3.0) / 4.0;
  const SpringBlock b(2, {{0, 1}, {1, 2}, {2, 0}}, VecX::Constant(3, k), VecX::Constant(3, edge));
  const Eigen::Matrix<double, 6, 1> x =
      Eigen::Map<const Eigen::Matrix<double, 6, 1>>(Eigen::Matrix<double, 3, 2, Eigen::RowMajor>(p).data());
  const Mat6 k_cst = fem::cst_stiffness(p, {material::Law::kLinear, e, 1.0 / 3.0, material::Plane::kStress, t});
  EXPECT_LT((MatX(hessian(b, x)) - k_cst).norm(), 1e-12 * k_cst.norm());
  // ... and only then: at nu = 0.25 the match is lost.
  const Mat6 k_quarter = fem::cst_stiffness(p, {material::Law::kLinear, e, 0.25, material::Plane::kStress, t});
  EXPECT_GT((MatX(hessian(b, x)) - k_quarter).norm(), 1e-2 * k_quarter.norm());
}

// Lloyd Sec. 4.1, Eq. 10-11: edge springs 5/16 t E with l0 = 6/5 L and diagonals 7/16 t E with l0 = 6/7 L sqrt 2
// on a square reproduce the bilinear (Q4) element at nu = 1/3 exactly, and are in equilibrium at rest. This
// holds only with the prestrained form of the spring Hessian, k[(1 - l0/l) I + (l0/l) u u^T]; Eq. 6 alone
// (valid at l = l0) would not match.
TEST(LloydSquare, PrestrainedSpringsEqualBilinearQuadAtNuOneThird) {
  const double e = 14630.0, t = 0.001, side = 0.01;
  Eigen::Matrix<double, 4, 2> p;
  p << 0, 0, side, 0, side, side, 0, side;
  const SpringBlock b(
      2, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}, {1, 3}},
      (VecX(6) << VecX::Constant(4, 5.0 / 16.0 * t * e), VecX::Constant(2, 7.0 / 16.0 * t * e)).finished(),
      (VecX(6) << VecX::Constant(4, 1.2 * side), VecX::Constant(2, 6.0 / 7.0 * std::sqrt(2.0) * side)).finished());
  VecX x(8);
  for (int a = 0; a < 4; ++a) x.segment<2>(2 * a) = p.row(a).transpose();
  VecX g = VecX::Zero(8);
  b.add_gradient(x, g);
  EXPECT_LT(g.norm(), 1e-12 * e * t * side) << "the prestrained square must be in equilibrium at rest";
  const Mat8 k_q4 = fem::quad4_stiffness(p, {material::Law::kLinear, e, 1.0 / 3.0, material::Plane::kStress, t});
  EXPECT_LT((MatX(hessian(b, x)) - k_q4).norm(), 1e-12 * k_q4.norm());
}

}  // namespace
}  // namespace hooke::springs

#include <hooke/core/symmetric_eigen.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/springs/tet_volume_block.hpp>

namespace hooke::springs {
namespace {

TEST(TetVolumeBlock, GradientAndHessianMatchFiniteDifferences) {
  const mesh::Mesh m = mesh::tet_box(0.01, 0.01, 0.01, 1, 1, 2);
  VecX v0(m.element_count());
  for (int t = 0; t < m.element_count(); ++t) v0(t) = mesh::element_measure(m, t);
  const TetVolumeBlock b(m.elements, VecX::LinSpaced(m.element_count(), 1e-3, 3e-3), v0);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  VecX x = Eigen::Map<const VecX>(m.nodes.data(), m.nodes.size());
  EXPECT_DOUBLE_EQ(b.energy(x), 0.0);
  for (Eigen::Index i = 0; i < x.size(); ++i) x(i) += 0.001 * u(rng);
  test::expect_derivatives_match_finite_differences(b, 3, x, 1e-8, 1e-6);
}

}  // namespace
}  // namespace hooke::springs

namespace hooke::springs {
namespace {

// The erratum of App. C.2: on the unit tet, dE_V/dp1 of a compressed tet points along +(1,1,1) (the energy
// grows as p1 moves towards its opposite face), i.e. dV/dp1 = -(1,1,1)/6, the opposite of the printed formula.
TEST(TetVolumeBlock, UnitTetGradientHasTheCorrectedSigns) {
  RowMatXi tet(1, 4);
  tet << 0, 1, 2, 3;
  const TetVolumeBlock b(tet, VecX::Constant(1, 36.0), VecX::Constant(1, 1.0 / 3.0));  // V = 1/6 < V0
  VecX x(12);
  x << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  VecX g = VecX::Zero(12);
  b.add_gradient(x, g);
  // k_V (V - V0) / V0^2 = 36 (-1/6) * 9 = -54, times dV/dp.
  EXPECT_LT((g.segment<3>(0) - Vec3(9, 9, 9)).norm(), 1e-12);
  EXPECT_LT((g.segment<3>(3) - Vec3(-9, 0, 0)).norm(), 1e-12);
  EXPECT_LT((g.segment<3>(6) - Vec3(0, -9, 0)).norm(), 1e-12);
  EXPECT_LT((g.segment<3>(9) - Vec3(0, 0, -9)).norm(), 1e-12);
}

}  // namespace
}  // namespace hooke::springs
