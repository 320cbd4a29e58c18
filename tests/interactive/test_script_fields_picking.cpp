// Scripts (parsing and refusals that name the line), picking (a ray against a known surface), the colour fields
// (spring strain under a uniform stretch, distances) and the colour map.
#include <gtest/gtest.h>

#include <hooke/calibrate/model_factory.hpp>
#include <hooke/core/error.hpp>
#include <hooke/interactive/fields.hpp>
#include <hooke/interactive/picking.hpp>
#include <hooke/interactive/script.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/topology.hpp>

namespace hooke::interactive {
namespace {

TEST(Script, ParsesEveryCommand) {
  const auto s = parse_script(
      "# a demo\n"
      "0 grab 3 4\n"
      "0 grab-nearest 0 0 0.02   # the top\n"
      "0.1 drag 0.003 0 -1e-3 over 0.5\n"
      "\n"
      "0.7 release\n"
      "0.7 set poisson 0.45\n"
      "0.8 colormap error\n"
      "0.8 ghost stvk\n"
      "0.9 screenshot out.png\n"
      "1 pause\n1 resume\n1 reset\n1 quit\n",
      "demo.txt");
  ASSERT_EQ(s.size(), 12u);
  EXPECT_EQ(s[0].nodes, (std::vector<int>{3, 4}));
  EXPECT_EQ(s[1].action, ScriptAction::kGrabNearest);
  EXPECT_EQ(s[1].vector, Vec3(0, 0, 0.02));
  EXPECT_EQ(s[2].vector, Vec3(0.003, 0, -1e-3));
  EXPECT_EQ(s[2].duration, 0.5);
  EXPECT_EQ(s[2].line, 4);
  EXPECT_EQ(s[4].key, "poisson");
  EXPECT_EQ(s[4].value, "0.45");
  EXPECT_TRUE(is_drawing(s[5].action));
  EXPECT_EQ(s[7].key, "out.png");
  EXPECT_FALSE(is_drawing(s[8].action));
  EXPECT_EQ(s[11].action, ScriptAction::kQuit);
  const auto t = parse_script(
      "0 tool sphere:0.005 0 0 0.03 friction 0.3\n0.1 move-tool 0 0 0.022 over 0.3\n0.5 move-tool 0 0 0.03\n"
      "0.6 tool capsule:0.001,0.01 0 0 0.04\n0.7 tool none\n",
      "tool.txt");
  ASSERT_EQ(t.size(), 5u);
  EXPECT_EQ(t[0].action, ScriptAction::kTool);
  EXPECT_EQ(t[0].key, "sphere:0.005");
  EXPECT_EQ(t[0].vector, Vec3(0, 0, 0.03));
  EXPECT_EQ(t[0].friction, 0.3);
  EXPECT_EQ(t[1].action, ScriptAction::kMoveTool);
  EXPECT_EQ(t[1].vector, Vec3(0, 0, 0.022));
  EXPECT_EQ(t[1].duration, 0.3);
  EXPECT_EQ(t[2].duration, 0.0);
  EXPECT_EQ(t[3].friction, 0.0);
  EXPECT_EQ(t[4].key, "none");
  EXPECT_FALSE(is_drawing(t[1].action));
}

TEST(Script, RefusalsNameTheLine) {
  const std::pair<const char*, const char*> bad[] = {
      {"0 grab 1\n0.5 jump\n", "unknown command 'jump'"},
      {"0 grab x\n", "not a node number"},
      {"0 grab -1\n", "not a node number"},
      {"0 drag 1 2\n", "missing offset"},
      {"0 drag 1 2 3 during 4\n", "over SECONDS"},
      {"0 drag 1 2 3 over -1\n", ">= 0"},
      {"1 release\n0.5 release\n", "must not decrease"},
      {"nan release\n", "finite number"},
      {"0 set colour red\n", "unknown setting"},
      {"0 colormap rainbow\n", "unknown colour map"},
      {"0 ghost on\n", "off, linear or stvk"},
      {"0 release now\n", "unexpected 'now'"},
      {"0 tool cube:1 0 0 0\n", "tool 'cube:1'"},
      {"0 tool sphere:0.01 0 0\n", "missing position"},
      {"0 tool sphere:0.01 0 0 0 mu 0.3\n", "friction MU"},
      {"0 tool sphere:0.01 0 0 0 friction -1\n", ">= 0"},
      {"0 move-tool 0 0 0.01 over -1\n", ">= 0"},
  };
  for (const auto& [text, what] : bad) {
    try {
      parse_script(text, "s.txt");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const ParseError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("s.txt"), std::string::npos) << e.what();
      EXPECT_GE(e.line(), 1);
    }
  }
  EXPECT_THROW(read_script("/nonexistent/script.txt"), IoError);
}

TEST(Picking, HitsTheNearestFaceOfABox) {
  const mesh::Mesh box = mesh::tet_box(0.02, 0.02, 0.02, 2, 2, 2);
  const RowMatXi faces = mesh::boundary_facets(box);
  const RowMatX x = positions_3d(VecX(Eigen::Map<const VecX>(box.nodes.data(), box.nodes.size())), 3);
  // From above, straight down through (0.011, 0.004): the top face z = 0.02 at distance 0.08.
  const auto hit = pick_surface(x, faces, Vec3(0.011, 0.004, 0.1), Vec3(0, 0, -1));
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->distance, 0.08, 1e-12);
  EXPECT_NEAR(hit->point(2), 0.02, 1e-12);
  EXPECT_NEAR(x(hit->nearest_node, 2), 0.02, 1e-12);
  // The nearest node of the hit triangle is the grid node (0.01, 0.0, 0.02).
  EXPECT_NEAR((x.row(hit->nearest_node) - Eigen::RowVector3d(0.01, 0.0, 0.02)).norm(), 0.0, 1e-12);
  // Missing the box, or pointing away from it: no hit.
  EXPECT_FALSE(pick_surface(x, faces, Vec3(0.05, 0.05, 0.1), Vec3(0, 0, -1)).has_value());
  EXPECT_FALSE(pick_surface(x, faces, Vec3(0.01, 0.01, 0.1), Vec3(0, 0, 1)).has_value());
  // From inside, the first face along the ray.
  const auto inside = pick_surface(x, faces, Vec3(0.011, 0.009, 0.005), Vec3(1, 0, 0));
  ASSERT_TRUE(inside.has_value());
  EXPECT_NEAR(inside->point(0), 0.02, 1e-12);
  // A grab radius takes the surface nodes within it, the nearest always.
  const std::vector<int> all = surface_view(box).nodes;  // the centre node (0.01, 0.01, 0.01) is not one
  EXPECT_EQ(nodes_within(x, all, hit->point, 0.0, hit->nearest_node), std::vector<int>{hit->nearest_node});
  EXPECT_EQ(nodes_within(x, all, Vec3(0.01, 0.01, 0.02), 0.0101, hit->nearest_node).size(), 5u);
}

TEST(Fields, PlanarPositionsMapToTheVerticalPlane) {
  VecX flat(4);
  flat << 1, 2, 3, 4;
  const RowMatX x = positions_3d(flat, 2);
  EXPECT_EQ(x.row(1), Eigen::RowVector3d(3, 0, 4));
  EXPECT_EQ(from_3d(Vec3(5, 6, 7), 2), (VecX(2) << 5, 7).finished());
  EXPECT_EQ(from_3d(Vec3(5, 6, 7), 3), Vec3(5, 6, 7));
}

TEST(Fields, SpringStrainOfAUniformStretchIsTheStretch) {
  const mesh::Mesh m = mesh::tet_box(0.02, 0.02, 0.02, 2, 2, 2);
  const calibrate::CalibratedModel cm = calibrate::calibrate_model(m, {material::Law::kLinear, 1e4, 0.25}, {});
  VecX x(3 * m.node_count());
  for (int i = 0; i < m.node_count(); ++i) x.segment<3>(3 * i) = 1.03 * m.nodes.row(i).transpose();
  const VecX strain = spring_strain(cm.springs, x, m.node_count());
  EXPECT_NEAR(strain.minCoeff(), 0.03, 1e-12);
  EXPECT_NEAR(strain.maxCoeff(), 0.03, 1e-12);
  const VecX rest = Eigen::Map<const VecX>(m.nodes.data(), m.nodes.size());
  const VecX d = displacement_magnitude(x, rest, 3);
  for (int i = 0; i < m.node_count(); ++i) EXPECT_NEAR(d(i), 0.03 * m.nodes.row(i).norm(), 1e-15);
  EXPECT_NEAR(node_distance(x, x, 3).norm(), 0.0, 0.0);
}

TEST(Fields, SurfaceViewOfTetsIsTheBoundary) {
  const mesh::Mesh m = mesh::tet_box(0.02, 0.02, 0.02, 2, 2, 2);
  const SurfaceView v = surface_view(m);
  EXPECT_EQ(v.triangles.rows(), 6 * 2 * 2 * 2);  // 6 faces, 2 x 2 squares, 2 triangles each
  EXPECT_EQ(v.nodes.size(), 26u);                // the 27 grid nodes but the centre
  EXPECT_EQ(color_field_from_name("strain"), ColorField::kStrain);
  EXPECT_THROW(color_field_from_name("heat"), InvalidArgument);
}

// E per node: one material everywhere, or with a stiffer region the largest of each node's elements'.
TEST(Fields, YoungsModulusPerNodeShowsTheRegions) {
  mesh::Mesh m = mesh::tet_box(0.02, 0.02, 0.02, 2, 2, 2);
  calibrate::ModelOptions o;
  o.method = "any-nu-tet";
  const material::Material soft{material::Law::kLinear, 5000.0, 0.45};
  EXPECT_EQ(node_youngs_modulus(calibrate::calibrate_model(m, soft, o)), VecX::Constant(27, 5000.0));
  for (int e = 0; e < m.element_count(); ++e) m.region(e) = e < 6 ? 2 : 1;  // the first cube's six tets
  o.regions = {{2, 25000.0, 0.45}};
  const VecX young = node_youngs_modulus(calibrate::calibrate_model(m, soft, o));
  int stiff = 0;
  for (int i = 0; i < 27; ++i) {
    bool in_first_cube = false;
    for (int e = 0; e < 6; ++e)
      for (int k = 0; k < 4; ++k) in_first_cube |= m.elements(e, k) == i;
    EXPECT_EQ(young(i), in_first_cube ? 25000.0 : 5000.0) << i;
    stiff += in_first_cube;
  }
  EXPECT_EQ(stiff, 8);
  EXPECT_EQ(color_field_from_name("young"), ColorField::kYoung);
  EXPECT_EQ(color_field_unit(ColorField::kYoung), "Pa");
}

TEST(Fields, ColourMapIsOrderedAndClamped) {
  double last = -1.0;
  for (int k = 0; k <= 20; ++k) {
    const auto c = colormap(k / 20.0);
    const double luma = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    EXPECT_GT(luma, last);  // lightness rises: the map reads as an order in grey too
    last = luma;
  }
  EXPECT_EQ(colormap(-3.0), colormap(0.0));
  EXPECT_EQ(colormap(7.0), colormap(1.0));
  EXPECT_EQ(colormap(std::nan("")), colormap(0.0));
}

}  // namespace
}  // namespace hooke::interactive
