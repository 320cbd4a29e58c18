#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/mesh/topology.hpp>
#include <hooke/mesh/validate.hpp>
#include <map>

namespace hooke::mesh {
namespace {

TEST(Generators, LloydEquilateralMembraneCounts) {
  // Lloyd Sec. 5.1: 39 nodes, 92 springs, 5.2 cm high.
  Mesh m = equilateral_membrane(7, 6, 0.01);
  EXPECT_EQ(validate(m).reoriented_elements, 0);
  EXPECT_EQ(m.node_count(), 39);
  EXPECT_EQ(unique_edges(m).size(), 92u);
  EXPECT_NEAR(m.nodes.col(1).maxCoeff(), 0.052, 0.0005);
  for (const auto& e : unique_edges(m)) EXPECT_NEAR((m.nodes.row(e[0]) - m.nodes.row(e[1])).norm(), 0.01, 1e-12);
}

TEST(Generators, HexagonIsEquilateralAndHasTheRightArea) {
  Mesh m = hexagon_membrane(3, 0.01);
  EXPECT_EQ(validate(m).reoriented_elements, 0);
  double area = 0;
  for (int e = 0; e < m.element_count(); ++e) area += element_measure(m, e);
  EXPECT_NEAR(area, 1.5 * std::sqrt(3.0) * 1e-4, 1e-15);
  EXPECT_EQ(m.element_count(), 6 * 9);
}

TEST(Generators, SquareMeshCountsOfLloydSec53) {
  // 5 x 5 squares: 36 nodes, 60 edges + 50 diagonals = 110 springs.
  Mesh m = rectangle_quads(0.05, 0.05, 5, 5);
  EXPECT_EQ(validate(m).reoriented_elements, 0);
  EXPECT_EQ(m.node_count(), 36);
  EXPECT_EQ(unique_edges(m).size() + 2 * m.element_count(), 110u);
}

TEST(Generators, TetBoxFillsItsVolumeWithPositiveTets) {
  Mesh m = tet_box(0.02, 0.03, 0.04, 3, 4, 5);
  EXPECT_EQ(validate(m).reoriented_elements, 0);
  double v = 0;
  for (int e = 0; e < m.element_count(); ++e) v += element_measure(m, e);
  EXPECT_NEAR(v, 0.02 * 0.03 * 0.04, 1e-15);
  EXPECT_EQ(m.node_count(), 4 * 5 * 6);
  // Conforming: every interior face is shared, so the boundary area is the box's surface area.
  const RowMatXi f = boundary_facets(m);
  EXPECT_NEAR(facet_measures(m, f).sum(), 2 * (0.02 * 0.03 + 0.03 * 0.04 + 0.02 * 0.04), 1e-14);
}

class CubeSurface : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(CubeSurface, NodeCountsOfArnabTable1AndOutwardOrientation) {
  const auto [n, nodes] = GetParam();
  Mesh m = cube_surface(n, 0.1);
  validate(m);
  EXPECT_EQ(m.node_count(), nodes);
  EXPECT_EQ(m.element_count(), 12 * n * n);
  // Divergence theorem: the enclosed volume is sum over faces of (x . n) A / 3 > 0 only if normals point out.
  double volume = 0;
  for (int e = 0; e < m.element_count(); ++e) {
    const Vec3 a = m.nodes.row(m.elements(e, 0)).transpose(), b = m.nodes.row(m.elements(e, 1)).transpose(),
               c = m.nodes.row(m.elements(e, 2)).transpose();
    volume += a.dot(b.cross(c)) / 6.0;
  }
  EXPECT_NEAR(volume, 1e-3, 1e-15);
  // Closed: every edge is shared by exactly two triangles (Euler characteristic 2).
  EXPECT_EQ(m.node_count() - static_cast<int>(unique_edges(m).size()) + m.element_count(), 2);
}

INSTANTIATE_TEST_SUITE_P(Table1, CubeSurface,
                         ::testing::Values(std::pair{10, 602}, std::pair{15, 1352}, std::pair{20, 2402}));

}  // namespace
}  // namespace hooke::mesh

namespace hooke::mesh {
namespace {

// The benchmark cylinders: node counts as documented, every tet positive, the concentric map keeps each cell's
// volume, so the total is the inscribed polygonal prism's (pi r^2 h from below).
TEST(Generators, TetCylinderCountsAndPositiveVolumes) {
  const Mesh m = tet_cylinder(0.01, 0.02, 12, 8);  // O-grid: 6 x 6 square cells, a ring of 24 x 3
  EXPECT_EQ(m.node_count(), (7 * 7 + 24 * 3) * 9);
  EXPECT_EQ(m.element_count(), 6 * (36 + 72) * 8);
  double total = 0.0, smallest = 1.0;
  for (int e = 0; e < m.element_count(); ++e) {
    total += element_measure(m, e);
    smallest = std::min(smallest, element_measure(m, e));
  }
  EXPECT_GT(smallest, 0.0);
  // The tets fill the prism over the 24-gon inscribed in the circle (4 x 6 rim nodes at equal angles) exactly.
  const double polygon = 12.0 * 1e-4 * std::sin(2.0 * M_PI / 24.0),
               perimeter = 24.0 * 2.0 * 0.01 * std::sin(M_PI / 24.0);
  EXPECT_NEAR(total, polygon * 0.02, 1e-12 * total);
  EXPECT_NEAR(m.nodes.col(0).cwiseAbs().maxCoeff(), 0.01, 1e-15);
  Mesh checked = m;
  EXPECT_NO_THROW(validate(checked, {.fix_orientation = false}));  // positive, nothing degenerate
  // No slivers: the square-to-disc map it replaces made tets of quality 0.03 in the square's corner cells.
  double worst = 1.0;
  for (int e = 0; e < m.element_count(); ++e) worst = std::min(worst, element_quality(m, e));
  EXPECT_GT(worst, 0.25);
  // Conforming: every interior triangle is shared by exactly two tets, so the faces used once are exactly the
  // prism's surface (two 24-gons and the rim).
  std::map<std::array<int, 3>, int> faces;
  for (int e = 0; e < m.element_count(); ++e)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> f{};
      for (int k = 0, q = 0; k < 4; ++k)
        if (k != skip) f[static_cast<size_t>(q++)] = m.elements(e, k);
      std::sort(f.begin(), f.end());
      ++faces[f];
    }
  double area = 0.0;
  for (const auto& [f, count] : faces) {
    ASSERT_LE(count, 2);
    if (count == 1) {
      const Vec3 a = m.nodes.row(f[0]), b = m.nodes.row(f[1]), c = m.nodes.row(f[2]);
      area += 0.5 * (b - a).cross(c - a).norm();
    }
  }
  EXPECT_NEAR(area, 2.0 * polygon + perimeter * 0.02, 1e-12 * area);
}

}  // namespace
}  // namespace hooke::mesh
