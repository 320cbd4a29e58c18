// Self-intersection of triangle surfaces: a closed cube is clean, a cube pushed through itself is found with the
// pair named, touching and neighbouring triangles are not reported, and the grid finds what brute force finds.
#include <gtest/gtest.h>

#include <hooke/core/error.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/self_intersection.hpp>

namespace hooke::mesh {
namespace {

Mesh two_triangles(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e, const Vec3& f) {
  RowMatX nodes(6, 3);
  nodes << a.transpose(), b.transpose(), c.transpose(), d.transpose(), e.transpose(), f.transpose();
  RowMatXi tris(2, 3);
  tris << 0, 1, 2, 3, 4, 5;
  return make_mesh(ElementKind::kSurfaceTriangle, nodes, tris, "pair");
}

TEST(SelfIntersection, ClosedSurfacesAreClean) {
  EXPECT_TRUE(self_intersections(cube_surface(6, 0.1)).empty());
  EXPECT_TRUE(self_intersections(uv_sphere_surface(12, 20, 0.05)).empty());
  EXPECT_NO_THROW(require_no_self_intersection(cube_surface(3, 1.0)));
}

TEST(SelfIntersection, CrossingPairIsFoundAndTouchingIsNot) {
  // A horizontal triangle pierced by a vertical one.
  const Mesh crossing =
      two_triangles({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.2, -0.5}, {0.3, 0.2, 0.5}, {0.25, 0.4, 0.5});
  ASSERT_EQ(self_intersections(crossing).size(), 1u);
  // The vertical one lifted until it only touches the plane at its lowest node: no crossing.
  const Mesh touching =
      two_triangles({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.2, 0.0}, {0.3, 0.2, 1.0}, {0.25, 0.4, 1.0});
  EXPECT_TRUE(self_intersections(touching).empty());
  // Beside each other, boxes overlapping: no crossing.
  const Mesh apart = two_triangles({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.6, 0.6, -0.5}, {0.9, 0.6, 0.5}, {0.8, 0.9, 0.5});
  EXPECT_TRUE(self_intersections(apart).empty());
}

TEST(SelfIntersection, DentPushedThroughTheOppositeFaceIsNamed) {
  Mesh m = cube_surface(4, 1.0);
  // The centre node of the top face pushed down through the bottom face.
  int top = -1;
  for (int i = 0; i < m.node_count(); ++i)
    if (std::abs(m.nodes(i, 2) - 1.0) < 1e-12 && std::abs(m.nodes(i, 0) - 0.5) < 1e-12 &&
        std::abs(m.nodes(i, 1) - 0.5) < 1e-12)
      top = i;
  ASSERT_GE(top, 0);
  // Off the symmetry lines, so that the crossings are generic (not on the bottom face's edges).
  m.nodes.row(top) << 0.52, 0.47, -0.5;
  const auto pairs = self_intersections(m, 1000);
  ASSERT_FALSE(pairs.empty());
  // Brute force over all pairs agrees with the grid.
  std::vector<std::array<int, 2>> brute;
  for (int s = 0; s < m.element_count(); ++s)
    for (int t = s + 1; t < m.element_count(); ++t) {
      Mesh pair = m;
      pair.elements.resize(2, 3);
      pair.elements.row(0) = m.elements.row(s);
      pair.elements.row(1) = m.elements.row(t);
      if (!self_intersections(pair).empty()) brute.push_back({s, t});
    }
  EXPECT_EQ(pairs, brute);
  try {
    require_no_self_intersection(m);
    FAIL() << "no error";
  } catch (const InvalidMesh& e) {
    EXPECT_NE(std::string(e.what()).find("cross each other"), std::string::npos) << e.what();
    EXPECT_EQ(e.element(), pairs[0][0]);
  }
}

}  // namespace
}  // namespace hooke::mesh
