// Closed-surface checks of the surface model: holes, non-manifold edges and nodes, orientation repair,
// several pieces, and the star-shape condition of the radial construction, each named in the error.
#include <gtest/gtest.h>

#include <hooke/core/error.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/surface/closed_surface.hpp>

namespace hooke::surface {
namespace {

std::string error_of(mesh::Mesh m) {
  try {
    check_closed_surface(m);
  } catch (const InvalidMesh& e) {
    return e.what();
  }
  return "";
}

TEST(ClosedSurface, CubeIsClosedWithItsVolumeAndCentroid) {
  mesh::Mesh m = mesh::cube_surface(4, 0.2);
  const SurfaceCheckReport r = check_closed_surface(m);
  EXPECT_EQ(r.flipped_triangles, 0);
  EXPECT_FALSE(r.reversed_all);
  EXPECT_NEAR(r.volume, 0.008, 1e-15);
  EXPECT_LT((volume_centroid(m) - Vec3(0.1, 0.1, 0.1)).norm(), 1e-15);
}

TEST(ClosedSurface, FlippedTrianglesAndInwardSurfacesAreRepaired) {
  mesh::Mesh m = mesh::cube_surface(3, 1.0);
  const mesh::Mesh original = m;
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
  mesh::Mesh m = mesh::cube_surface(2, 1.0);
  mesh::Mesh hole = m;
  hole.elements.conservativeResize(m.element_count() - 1, 3);
  EXPECT_NE(error_of(hole).find("hole"), std::string::npos) << error_of(hole);
  mesh::Mesh tripled = m;
  tripled.elements.conservativeResize(m.element_count() + 1, 3);
  tripled.elements.row(m.element_count()) << m.elements(0, 0), m.elements(0, 1), m.elements(3, 2);
  EXPECT_NE(error_of(tripled).find("three or more triangles"), std::string::npos) << error_of(tripled);
  // Two cubes side by side: two pieces.
  mesh::Mesh two = m;
  const int n = m.node_count();
  two.nodes.conservativeResize(2 * n, 3);
  two.nodes.bottomRows(n) = m.nodes.array() + 3.0;
  two.elements.conservativeResize(2 * m.element_count(), 3);
  two.elements.bottomRows(m.element_count()) = m.elements.array() + n;
  EXPECT_NE(error_of(two).find("several separate pieces"), std::string::npos) << error_of(two);
  mesh::Mesh tets = mesh::tet_box(1, 1, 1, 1, 1, 1);
  EXPECT_NE(error_of(tets).find("closed triangle surface"), std::string::npos);
}

TEST(ClosedSurface, RadialConstructionNeedsAStarShapedSurface) {
  mesh::Mesh m = mesh::cube_surface(4, 1.0);
  check_closed_surface(m);
  EXPECT_NO_THROW(require_star_shaped(m, Vec3(0.5, 0.5, 0.5)));
  EXPECT_NO_THROW(require_star_shaped(m, Vec3(0.2, 0.7, 0.4)));  // any interior point of a convex body
  try {
    require_star_shaped(m, Vec3(1.5, 0.5, 0.5));  // outside
    FAIL() << "no error";
  } catch (const InvalidMesh& e) {
    EXPECT_NE(std::string(e.what()).find("not star-shaped"), std::string::npos) << e.what();
    EXPECT_GE(e.element(), 0);
  }
  // Push one face's centre node deep inside: the surface is no longer star-shaped from the centre.
  mesh::Mesh dent = m;
  int top = -1;
  for (int i = 0; i < dent.node_count(); ++i)
    if (std::abs(dent.nodes(i, 2) - 1.0) < 1e-12 && std::abs(dent.nodes(i, 0) - 0.5) < 1e-12 &&
        std::abs(dent.nodes(i, 1) - 0.5) < 1e-12)
      top = i;
  ASSERT_GE(top, 0);
  dent.nodes(top, 2) = 0.3;
  EXPECT_THROW(require_star_shaped(dent, Vec3(0.5, 0.5, 0.5)), InvalidMesh);
}

}  // namespace
}  // namespace hooke::surface
