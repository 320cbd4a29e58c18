#include <gtest/gtest.h>

#include <hooke/core/error.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/model/load_case.hpp>
#include <support/meshes.hpp>

namespace hooke::model {
namespace {

TEST(LoadCase, ForcesSumToTractionTimesTopArea) {
  const mesh::Mesh cyl = io::read_mesh(HOOKE_MESH_DATA "/cylinder.msh");
  for (LoadKind k : {LoadKind::kStretch, LoadKind::kCompress, LoadKind::kShear}) {
    const LoadCase lc = make_load_case(cyl, k, 250.0);
    Vec3 total = Vec3::Zero();
    for (int i = 0; i < cyl.node_count(); ++i) total += lc.nodal_forces.segment<3>(3 * i);
    // The top is a polygon inscribed in the 1 cm disc (about 10 sides on this coarse mesh): ~6 % below pi r^2.
    EXPECT_LT(lc.top_area, M_PI * 1e-4);
    EXPECT_GT(lc.top_area, 0.9 * M_PI * 1e-4);
    EXPECT_NEAR((total - 250.0 * lc.top_area * Vec3(lc.direction)).norm(), 0.0, 1e-12);
    EXPECT_NEAR(lc.height, 0.02, 1e-12);
  }
  EXPECT_EQ(make_load_case(cyl, LoadKind::kShear, 1.0).direction, Vec3(0, 1, 0));
}

TEST(LoadCase, PlanarTractionUsesThickness) {
  const mesh::Mesh m = mesh::rectangle_quads(0.05, 0.05, 5, 5);
  const LoadCase lc = make_load_case(m, LoadKind::kShear, 100.0, 0.002);
  EXPECT_NEAR(lc.top_area, 0.05 * 0.002, 1e-15);
  EXPECT_NEAR(lc.nodal_forces.sum(), 100.0 * 0.05 * 0.002, 1e-15);
  EXPECT_EQ(lc.fixed_nodes.size(), 6u);
}

TEST(LoadCase, MeshWithoutFlatTopIsRejected) {
  const mesh::Mesh surface = mesh::cube_surface(2, 1.0);
  EXPECT_THROW(make_load_case(surface, LoadKind::kStretch, 1.0), InvalidArgument);
}

}  // namespace
}  // namespace hooke::model
