// Closed-surface checks: holes, non-manifold edges and nodes, orientation repair and several pieces, each named in
// the error; the enclosed volume and its centroid.
#include <gtest/gtest.h>

#include <hooke/core/error.hpp>
#include <hooke/mesh/closed_surface.hpp>
#include <hooke/mesh/generators.hpp>

namespace hooke::mesh {
namespace {

std::string closed_surface_error(Mesh m) {
  try {
    check_closed_surface(m);
  } catch (const InvalidMesh& e) {
    return e.what();
  }
  return "";
}

TEST(ClosedSurface, CubeIsClosedWithItsVolumeAndCentroid) {
  Mesh m = cube_surface(4, 0.2);
  const SurfaceCheckReport r = check_closed_surface(m);
  EXPECT_EQ(r.flipped_triangles, 0);
  EXPECT_FALSE(r.reversed_all);
  EXPECT_NEAR(r.volume, 0.008, 1e-15);
  EXPECT_LT((volume_centroid(m) - Vec3(0.1, 0.1, 0.1)).norm(), 1e-15);
}

TEST(ClosedSurface, FlippedTrianglesAndInwardSurfacesAreRepaired) {
  Mesh m = cube_surface(3, 1.0);
  const Mesh original = m;
  std::swap(m.elements(5, 1), m.elements(5, 2));
  std::swap(m.elements(17, 1), m.elements(17, 2));
  const SurfaceCheckReport r = check_closed_surface(m);
  EXPECT_EQ(r.flipped_triangles, 2);
  EXPECT_EQ(m.elements, original.elements);
  for (int t = 0; t < m.element_count(); ++t) std::swap(m.elements(t, 1), m.elements(t, 2));
  const SurfaceCheckReport inward = check_closed_surface(m);
  EXPECT_TRUE(inward.reversed_all);
  EXPECT_NEAR(inward.volume, 1.0, 1e-12);
}

TEST(ClosedSurface, NamesHolesNonManifoldEdgesAndPieces) {
  Mesh m = cube_surface(2, 1.0);
  Mesh hole = m;
  hole.elements.conservativeResize(m.element_count() - 1, 3);
  EXPECT_NE(closed_surface_error(hole).find("hole"), std::string::npos) << closed_surface_error(hole);
  Mesh tripled = m;
  tripled.elements.conservativeResize(m.element_count() + 1, 3);
  tripled.elements.row(m.element_count()) << m.elements(0, 0), m.elements(0, 1), m.elements(3, 2);
  EXPECT_NE(closed_surface_error(tripled).find("three or more triangles"), std::string::npos)
      << closed_surface_error(tripled);
  // Two cubes side by side: two pieces.
  Mesh two = m;
  const int n = m.node_count();
  two.nodes.conservativeResize(2 * n, 3);
  two.nodes.bottomRows(n) = m.nodes.array() + 3.0;
  two.elements.conservativeResize(2 * m.element_count(), 3);
  two.elements.bottomRows(m.element_count()) = m.elements.array() + n;
  EXPECT_NE(closed_surface_error(two).find("several separate pieces"), std::string::npos) << closed_surface_error(two);
  Mesh tets = tet_box(1, 1, 1, 1, 1, 1);
  EXPECT_NE(closed_surface_error(tets).find("closed triangle surface"), std::string::npos);
}

}  // namespace
}  // namespace hooke::mesh
