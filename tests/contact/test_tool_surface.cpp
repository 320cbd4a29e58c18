// The drawn surface of a tool against the tool's own distance: every node on the surface, closed and outward, and
// enclosing the solid's volume.
#include <gtest/gtest.h>

#include <cmath>
#include <hooke/contact/tool_surface.hpp>
#include <hooke/core/error.hpp>
#include <map>
#include <numbers>
#include <utility>

namespace hooke::contact {
namespace {

// The volume the triangles enclose (divergence theorem; > 0 when they face outwards), m^3, and whether every
// directed edge has its reverse exactly once (closed, consistently oriented).
std::pair<double, bool> enclosed(const ToolSurface& s) {
  double v = 0.0;
  std::map<std::pair<int, int>, int> edges;
  for (Eigen::Index f = 0; f < s.triangles.rows(); ++f) {
    const Vec3 a = s.nodes.row(s.triangles(f, 0)), b = s.nodes.row(s.triangles(f, 1)),
               c = s.nodes.row(s.triangles(f, 2));
    v += a.dot(b.cross(c)) / 6.0;
    for (int k = 0; k < 3; ++k) ++edges[{s.triangles(f, k), s.triangles(f, (k + 1) % 3)}];
  }
  bool closed = true;
  for (const auto& [e, count] : edges) closed = closed && count == 1 && edges.count({e.second, e.first}) == 1;
  return {v, closed};
}

TEST(ToolSurface, LiesOnTheToolIsClosedFacesOutwardsAndEnclosesItsVolume) {
  const Pose pose{Vec3(0.01, -0.02, 0.03), Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 0.5).normalized()).toRotationMatrix()};
  for (const auto& [shape, exact] :
       {std::pair{RigidTool(ToolShape::kSphere, 0.005), 4.0 / 3.0 * std::numbers::pi * std::pow(0.005, 3)},
        std::pair{RigidTool(ToolShape::kCapsule, 0.002, 0.01),
                  4.0 / 3.0 * std::numbers::pi * std::pow(0.002, 3) + std::numbers::pi * 0.002 * 0.002 * 0.01}}) {
    RigidTool tool = shape;
    tool.set_pose(pose);
    const ToolSurface s = tool_surface(tool, 64);
    for (Eigen::Index i = 0; i < s.nodes.rows(); ++i)
      EXPECT_NEAR(tool.signed_distance(s.nodes.row(i).transpose()), 0.0, 1e-15) << tool.description();
    const auto [volume, closed] = enclosed(s);
    EXPECT_TRUE(closed) << tool.description();
    EXPECT_GT(volume, 0.99 * exact) << tool.description();  // inscribed: a little less than the solid
    EXPECT_LT(volume, exact) << tool.description();
  }
  RigidTool plane(ToolShape::kHalfSpace);
  plane.set_pose(pose);
  const ToolSurface p = tool_surface(plane, 8, 0.1);
  for (Eigen::Index i = 0; i < p.nodes.rows(); ++i)
    EXPECT_NEAR(plane.signed_distance(p.nodes.row(i).transpose()), 0.0, 1e-15);
  EXPECT_THROW(tool_surface(plane, 8, 0.0), InvalidArgument);
  EXPECT_THROW(tool_surface(RigidTool(ToolShape::kSphere, 0.01), 4), InvalidArgument);
}

}  // namespace
}  // namespace hooke::contact
