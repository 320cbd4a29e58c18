// Tet quality against closed forms: the regular tet (radius ratio 1, all dihedral angles acos(1/3)), the corner tet
// (angles 90 deg and acos(1/sqrt(3)), radius ratio from its in- and circumradius by hand), and slivers.
#include <gtest/gtest.h>

#include <cmath>
#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/tet_quality.hpp>
#include <numbers>

namespace hooke::mesh {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

TEST(TetQuality, RegularTetHasRatioOneAndEqualAngles) {
  const Vec3 a(1, 1, 1), b(1, -1, -1), c(-1, 1, -1), d(-1, -1, 1);
  EXPECT_NEAR(radius_ratio(a, b, c, d), 1.0, 1e-14);
  EXPECT_NEAR(radius_ratio(a, c, b, d), 1.0, 1e-14);  // orientation does not matter
  for (const double angle : dihedral_angles(a, b, c, d)) EXPECT_NEAR(angle, std::acos(1.0 / 3.0), 1e-14);
}

TEST(TetQuality, CornerTetMatchesItsClosedForm) {
  // Corner tet with unit legs: V = 1/6, faces 3 * 1/2 + sqrt(3)/2, r = 3V / S, R = sqrt(3)/2.
  const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  const double r = 0.5 / (1.5 + std::sqrt(3.0) / 2.0), circumradius = std::sqrt(3.0) / 2.0;
  EXPECT_NEAR(radius_ratio(o, x, y, z), 3.0 * r / circumradius, 1e-14);
  const auto angles = dihedral_angles(o, x, y, z);
  // Edges ox, oy, oz: the coordinate planes meet at 90 deg; edges xy, xz, yz: the slanted face against a
  // coordinate plane, acos(1/sqrt(3)) = 54.74 deg.
  for (int e = 0; e < 3; ++e) EXPECT_NEAR(angles[static_cast<size_t>(e)] * kDeg, 90.0, 1e-12);
  for (int e = 3; e < 6; ++e) EXPECT_NEAR(angles[static_cast<size_t>(e)], std::acos(1.0 / std::sqrt(3.0)), 1e-14);
}

TEST(TetQuality, SliverHasSmallRatioAndExtremeAngles) {
  // Four nodes of a square, two lifted by h: no short edge, volume -> 0 with h.
  const double h = 1e-3;
  const Vec3 a(0, 0, 0), b(1, 0, h), c(1, 1, 0), d(0, 1, h);
  EXPECT_LT(radius_ratio(a, b, c, d), 0.01);
  const auto angles = dihedral_angles(a, b, c, d);
  EXPECT_LT(*std::min_element(angles.begin(), angles.end()) * kDeg, 1.0);
  EXPECT_GT(*std::max_element(angles.begin(), angles.end()) * kDeg, 179.0);
  EXPECT_EQ(radius_ratio(a, b, c, Vec3(0.5, 0.5, 0.0)), 0.0);  // flat: the fourth node on the diagonal ac
}

TEST(TetQuality, MeshReportCountsTetsBelowTheFloor) {
  const Mesh m = tet_box(1, 1, 1, 2, 2, 2);
  const TetQualityReport r = tet_quality(m, 0.9);
  double lowest = 2.0;
  int below = 0;
  for (int e = 0; e < m.element_count(); ++e) {
    const auto p = [&](int k) { return Vec3(m.nodes.row(m.elements(e, k)).transpose()); };
    const double rho = radius_ratio(p(0), p(1), p(2), p(3));
    lowest = std::min(lowest, rho);
    below += rho < 0.9;
  }
  EXPECT_DOUBLE_EQ(r.min_radius_ratio, lowest);
  EXPECT_EQ(r.below_floor, below);
  EXPECT_GT(r.below_floor, 0);
  EXPECT_GT(r.min_dihedral, 0.0);
  EXPECT_LT(r.max_dihedral, 180.0);
  EXPECT_GE(r.worst_element, 0);
}

}  // namespace
}  // namespace hooke::mesh
