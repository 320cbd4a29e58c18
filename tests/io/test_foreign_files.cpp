// Files written by other tools (Gmsh 4.11, TetGen 1.6, meshio 7; see scripts/make_meshes.sh).
#include <gtest/gtest.h>

#include <hooke/io/mesh_io.hpp>
#include <hooke/io/vtu.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/mesh/topology.hpp>

namespace hooke::io {
namespace {

const std::string kData = HOOKE_TEST_DATA;

TEST(ForeignFiles, AllGmshFlavoursOfTheBoxAgree) {
  const mesh::Mesh ref = read_mesh(kData + "/gmsh_box_v41_ascii.msh");
  EXPECT_EQ(ref.kind, mesh::ElementKind::kTet);
  EXPECT_NEAR(total_measure(ref), 1e-6, 1e-15);
  EXPECT_EQ(ref.region(0), 7);  // Physical Volume(7)
  for (const char* f : {"gmsh_box_v22_ascii.msh", "gmsh_box_v22_binary.msh", "gmsh_box_v41_binary.msh"}) {
    const mesh::Mesh m = read_mesh(kData + "/" + f);
    EXPECT_EQ(m.node_count(), ref.node_count()) << f;
    EXPECT_EQ(m.element_count(), ref.element_count()) << f;
    EXPECT_NEAR(total_measure(m), 1e-6, 1e-15) << f;
    EXPECT_EQ(m.region(0), 7) << f;
  }
}

TEST(ForeignFiles, GmshPlanarTrianglesAndQuads) {
  const mesh::Mesh tri = read_mesh(kData + "/gmsh_square_v41_ascii.msh");
  EXPECT_EQ(tri.kind, mesh::ElementKind::kTriangle);
  EXPECT_NEAR(total_measure(tri), 4e-4, 1e-15);
  const mesh::Mesh quad = read_mesh(kData + "/gmsh_square_quads_v22_binary.msh");
  EXPECT_EQ(quad.kind, mesh::ElementKind::kQuad);
  EXPECT_NEAR(total_measure(quad), 4e-4, 1e-15);
}

TEST(ForeignFiles, TetGenCube) {
  for (const char* f : {"/tetgen_cube.1.ele", "/tetgen_cube.1.node"}) {
    const mesh::Mesh m = read_mesh(kData + f);
    EXPECT_EQ(m.kind, mesh::ElementKind::kTet);
    EXPECT_NEAR(total_measure(m), 1.0, 1e-12);
  }
  const mesh::Mesh faces = read_mesh(kData + "/tetgen_cube.1.face");
  EXPECT_EQ(faces.kind, mesh::ElementKind::kSurfaceTriangle);
  EXPECT_NEAR(total_measure(faces), 6.0, 1e-12);
}

TEST(ForeignFiles, MeshioSphereInEverySurfaceFormat) {
  const mesh::Mesh ref = read_mesh(HOOKE_MESH_DATA "/sphere_surface.msh");
  ASSERT_EQ(ref.kind, mesh::ElementKind::kSurfaceTriangle);
  const double area = total_measure(ref);
  EXPECT_NEAR(area, 4 * M_PI * 1e-4, 0.01 * 4 * M_PI * 1e-4);
  for (const char* f : {"meshio_sphere.stl", "meshio_sphere_ascii.stl", "meshio_sphere.obj", "meshio_sphere.off"}) {
    const mesh::Mesh m = read_mesh(kData + "/" + f);
    EXPECT_EQ(m.kind, mesh::ElementKind::kSurfaceTriangle) << f;
    EXPECT_EQ(m.node_count(), ref.node_count()) << f;  // STL vertices welded back together
    EXPECT_EQ(m.element_count(), ref.element_count()) << f;
    EXPECT_NEAR(total_measure(m), area, 1e-6 * area) << f;
  }
}

TEST(ForeignFiles, MeshioVtuWithPointData) {
  const VtuContents c = read_vtu(kData + "/meshio_box.vtu");
  EXPECT_EQ(c.mesh.kind, mesh::ElementKind::kTet);
  ASSERT_EQ(c.point_data.size(), 1u);
  EXPECT_EQ(c.point_data[0].name, "height");
  for (int i = 0; i < c.mesh.node_count(); ++i) EXPECT_DOUBLE_EQ(c.point_data[0].values(i), c.mesh.nodes(i, 2));
}

}  // namespace
}  // namespace hooke::io
