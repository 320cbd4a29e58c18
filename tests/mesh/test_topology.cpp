#include <gtest/gtest.h>

#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/mesh/topology.hpp>

namespace hooke::mesh {
namespace {

TEST(Topology, BoundaryEdgesOfARectangleAreOrientedOutward) {
  const Mesh m = rectangle_triangles(2.0, 1.0, 4, 2);
  const RowMatXi f = boundary_facets(m);
  EXPECT_EQ(f.rows(), 2 * (4 + 2));
  EXPECT_NEAR(facet_measures(m, f).sum(), 6.0, 1e-12);
  const Vec2 centre(1.0, 0.5);
  for (Eigen::Index i = 0; i < f.rows(); ++i) {
    const Vec2 a = m.nodes.row(f(i, 0)).transpose(), b = m.nodes.row(f(i, 1)).transpose();
    const Vec2 outward((b - a).y(), -(b - a).x());
    EXPECT_GT(outward.dot(0.5 * (a + b) - centre), 0.0);
  }
}

TEST(Topology, BoundaryFacesOfATetBoxPointOutward) {
  const Mesh m = tet_box(1, 1, 1, 2, 2, 2);
  const RowMatXi f = boundary_facets(m);
  EXPECT_EQ(f.rows(), 6 * 2 * 4);
  const Vec3 centre(0.5, 0.5, 0.5);
  for (Eigen::Index i = 0; i < f.rows(); ++i) {
    const Vec3 a = m.nodes.row(f(i, 0)).transpose(), b = m.nodes.row(f(i, 1)).transpose(),
               c = m.nodes.row(f(i, 2)).transpose();
    EXPECT_GT((b - a).cross(c - a).dot((a + b + c) / 3.0 - centre), 0.0);
  }
}

}  // namespace
}  // namespace hooke::mesh
