// Every format writes what it reads: write a mesh, read it back, compare nodes, elements and regions.
#include <gtest/gtest.h>

#include <filesystem>
#include <hooke/core/error.hpp>
#include <hooke/io/csv.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/io/vtu.hpp>
#include <hooke/mesh/generators.hpp>
#include <support/meshes.hpp>
#include <support/scratch.hpp>

namespace hooke::io {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) { return test::scratch_file("hooke_io_tests", name); }

void expect_same(const mesh::Mesh& a, const mesh::Mesh& b, double tol, bool regions = true) {
  ASSERT_EQ(a.kind, b.kind);
  ASSERT_EQ(a.node_count(), b.node_count());
  ASSERT_EQ(a.element_count(), b.element_count());
  EXPECT_LE((a.nodes - b.nodes).cwiseAbs().maxCoeff(), tol);
  EXPECT_EQ(a.elements, b.elements);
  if (regions) {
    EXPECT_EQ(a.region, b.region);
  }
}

struct RoundTrip {
  std::string file;
  WriteOptions options;
  mesh::ElementKind kind;
  double tol;
};

mesh::Mesh sample(mesh::ElementKind kind) {
  switch (kind) {
    case mesh::ElementKind::kTriangle: return test::perturb_interior(mesh::rectangle_triangles(0.02, 0.01, 4, 3), 0.2);
    case mesh::ElementKind::kQuad: return test::perturb_interior(mesh::rectangle_quads(0.02, 0.01, 4, 3), 0.2);
    case mesh::ElementKind::kTet: return test::perturb_interior(mesh::tet_box(0.01, 0.01, 0.01, 2, 2, 2), 0.2);
    default: return mesh::cube_surface(3, 0.01);
  }
}

class FormatRoundTrip : public ::testing::TestWithParam<RoundTrip> {};

TEST_P(FormatRoundTrip, ReadsBackWhatItWrote) {
  const RoundTrip& c = GetParam();
  mesh::Mesh m = sample(c.kind);
  const bool keeps_regions = c.file.ends_with(".msh") || c.file.ends_with(".vtu") || c.file.ends_with(".ele");
  if (keeps_regions)
    for (int e = 0; e < m.element_count(); ++e) m.region(e) = 5;
  const fs::path path = scratch(c.file);
  write_mesh(path, m, c.options);
  const mesh::Mesh back = read_mesh(path);
  if (c.file.ends_with(".stl")) {
    // STL stores triangles with their coordinates; nodes are welded back in order of appearance.
    ASSERT_EQ(back.element_count(), m.element_count());
    ASSERT_EQ(back.node_count(), m.node_count());
    for (int e = 0; e < m.element_count(); ++e)
      for (int k = 0; k < 3; ++k)
        EXPECT_LE((m.nodes.row(m.elements(e, k)) - back.nodes.row(back.elements(e, k))).norm(), c.tol + 1e-18);
    return;
  }
  expect_same(m, back, c.tol, keeps_regions);
}

INSTANTIATE_TEST_SUITE_P(
    AllFormats, FormatRoundTrip,
    ::testing::Values(RoundTrip{"tri_v41.msh", {MshVersion::kV41, false}, mesh::ElementKind::kTriangle, 0},
                      RoundTrip{"quad_v41b.msh", {MshVersion::kV41, true}, mesh::ElementKind::kQuad, 0},
                      RoundTrip{"tet_v41b.msh", {MshVersion::kV41, true}, mesh::ElementKind::kTet, 0},
                      RoundTrip{"tet_v22.msh", {MshVersion::kV22, false}, mesh::ElementKind::kTet, 0},
                      RoundTrip{"tet_v22b.msh", {MshVersion::kV22, true}, mesh::ElementKind::kTet, 0},
                      RoundTrip{"surf_v22b.msh", {MshVersion::kV22, true}, mesh::ElementKind::kSurfaceTriangle, 0},
                      RoundTrip{"tet.vtu", {}, mesh::ElementKind::kTet, 0},
                      RoundTrip{"quad.vtu", {}, mesh::ElementKind::kQuad, 0},
                      RoundTrip{"tet.ele", {}, mesh::ElementKind::kTet, 0},
                      RoundTrip{"surf.obj", {}, mesh::ElementKind::kSurfaceTriangle, 0},
                      RoundTrip{"quad.obj", {}, mesh::ElementKind::kQuad, 0},
                      RoundTrip{"surf.off", {}, mesh::ElementKind::kSurfaceTriangle, 0},
                      RoundTrip{"tri.off", {}, mesh::ElementKind::kTriangle, 0},
                      RoundTrip{"surf_ascii.stl", {MshVersion::kV41, false}, mesh::ElementKind::kSurfaceTriangle, 0},
                      RoundTrip{
                          "surf_binary.stl", {MshVersion::kV41, true}, mesh::ElementKind::kSurfaceTriangle, 1e-9}),
    [](const auto& param_info) {
      std::string n = param_info.param.file;
      for (char& ch : n)
        if (ch == '.') ch = '_';
      return n;
    });

TEST(VtuRoundTrip, PointAndCellFieldsSurvive) {
  const mesh::Mesh m = sample(mesh::ElementKind::kTriangle);
  Field disp{"displacement", 2, VecX::LinSpaced(2 * m.node_count(), -1e-3, 2e-3)};
  Field err{"error", 1, VecX::LinSpaced(m.element_count(), 0.0, 1.0)};
  write_vtu(scratch("fields.vtu"), m, {disp}, {err});
  const VtuContents back = read_vtu(scratch("fields.vtu"));
  ASSERT_EQ(back.point_data.size(), 1u);
  EXPECT_EQ(back.point_data[0].components, 3);  // 2D vectors are padded for ParaView
  for (int i = 0; i < m.node_count(); ++i) {
    EXPECT_DOUBLE_EQ(back.point_data[0].values(3 * i), disp.values(2 * i));
    EXPECT_DOUBLE_EQ(back.point_data[0].values(3 * i + 1), disp.values(2 * i + 1));
  }
  ASSERT_EQ(back.cell_data.size(), 1u);
  EXPECT_EQ(back.cell_data[0].values, err.values);
}

TEST(VtuRoundTrip, FieldOfWrongSizeIsRejected) {
  const mesh::Mesh m = sample(mesh::ElementKind::kTet);
  EXPECT_THROW(write_vtu(scratch("bad.vtu"), m, {Field{"u", 3, VecX::Zero(5)}}), InvalidArgument);
  EXPECT_FALSE(fs::exists(scratch("bad.vtu")));
}

TEST(UnitOption, CentimetreFileBecomesMetres) {
  mesh::Mesh m = sample(mesh::ElementKind::kTet);
  m.nodes *= 100.0;  // "written in cm"
  write_mesh(scratch("cm.msh"), m);
  ReadOptions o;
  o.metres_per_unit = 0.01;
  const mesh::Mesh back = read_mesh(scratch("cm.msh"), o);
  EXPECT_NEAR(back.nodes.maxCoeff(), 0.01, 1e-15);
}

}  // namespace
}  // namespace hooke::io
