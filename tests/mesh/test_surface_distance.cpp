// Point-to-surface distance and the node Hausdorff distance against closed forms: points above a face, beyond an
// edge and beyond a corner of a cube; two concentric spheres.
#include <gtest/gtest.h>

#include <cmath>
#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/surface_distance.hpp>

namespace hooke::mesh {
namespace {

TEST(SurfaceDistance, CubeFaceEdgeAndCorner) {
  const Mesh cube = cube_surface(5, 1.0);
  const SurfaceDistance distance(cube.nodes, cube.elements);
  EXPECT_NEAR(distance(Vec3(0.3, 0.4, 1.25)), 0.25, 1e-14);   // above the top face
  EXPECT_NEAR(distance(Vec3(0.3, 0.4, 0.9)), 0.1, 1e-14);     // inside, nearest the top
  EXPECT_NEAR(distance(Vec3(1.3, 0.5, 1.4)), 0.5, 1e-14);     // beyond an edge: (0.3, 0.4)
  EXPECT_NEAR(distance(Vec3(-1.0, -2.0, -2.0)), 3.0, 1e-14);  // beyond a corner
  EXPECT_NEAR(distance(Vec3(40.0, 0.5, 0.5)), 39.0, 1e-12);   // far outside the grid
}

TEST(SurfaceDistance, HausdorffOfConcentricSpheresIsTheirGap) {
  const Mesh inner = uv_sphere_surface(16, 24, 1.0), outer = uv_sphere_surface(16, 24, 1.1);
  // Every node of the outer sphere is 0.1 from the inner sphere's nodes; the inner's faces are inside the sphere
  // of radius 1 by less than the chord sag, so the distance lies between 0.1 and 0.1 + sag.
  const double h = node_hausdorff_distance(inner.nodes, inner.elements, outer.nodes, outer.elements);
  const double sag = 1.1 * (1.0 - std::cos(M_PI / 16.0));
  EXPECT_GE(h, 0.1 - 1e-12);
  EXPECT_LE(h, 0.1 + sag);
  EXPECT_EQ(node_hausdorff_distance(inner.nodes, inner.elements, inner.nodes, inner.elements), 0.0);
}

}  // namespace
}  // namespace hooke::mesh
