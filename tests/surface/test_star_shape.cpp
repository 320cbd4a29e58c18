// The star-shape condition of Arnab & Raja's radial construction, named in the error.
#include <gtest/gtest.h>

#include <hooke/core/error.hpp>
#include <hooke/mesh/closed_surface.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/surface/star_shape.hpp>

namespace hooke::surface {
namespace {

TEST(StarShape, RadialConstructionNeedsAStarShapedSurface) {
  mesh::Mesh m = mesh::cube_surface(4, 1.0);
  mesh::check_closed_surface(m);
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
