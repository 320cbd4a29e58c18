// Surface to tets with Netgen: a sphere remeshed and a cube kept (volume, orientation, quality, fidelity), the
// refusals named (holes, self-crossing, wrong kinds, options), and real scans no one on the project made (CGAL's
// femur, head and bones from Debian's libcgal-demo).
#include <gtest/gtest.h>

#include <support/meshes.hpp>

#include <cmath>
#include <filesystem>
#include <hooke/core/error.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/mesh/closed_surface.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/mesh/tetrahedralize.hpp>
#include <hooke/mesh/topology.hpp>
#include <numbers>

namespace hooke::mesh {
namespace {

std::string error_of(const Mesh& surface, const TetrahedralizeOptions& o = {}) {
  try {
    tetrahedralize(surface, o);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

Mesh scan(const std::string& name) {
  const std::filesystem::path path = std::filesystem::path(HOOKE_SCAN_DATA) / name;
  if (!std::filesystem::exists(path))
    throw IoError(path.string() + " is missing: scripts/setup.sh installs it (Debian package libcgal-demo)");
  return io::read_mesh(path);
}

TEST(Tetrahedralize, RemeshedSphereKeepsItsVolumeAndShape) {
  const double radius = 0.05;
  const Mesh sphere = uv_sphere_surface(24, 36, radius);
  TetrahedralizeReport r;
  TetrahedralizeOptions o;
  o.surface = SurfaceMeshing::kRemesh;
  o.max_size = radius / 8.0;  // chord sag size^2 / (8 R): about 0.6 % of the volume
  const Mesh tets = tetrahedralize(sphere, o, &r);
  ASSERT_EQ(tets.kind, ElementKind::kTet);
  double volume = 0.0;
  for (int e = 0; e < tets.element_count(); ++e) {
    ASSERT_GT(element_measure(tets, e), 0.0) << e;
    volume += element_measure(tets, e);
  }
  EXPECT_NEAR(volume, r.volume, 1e-15);
  EXPECT_NEAR(r.surface_volume, enclosed_volume(sphere.elements, flat_positions(sphere)), 1e-18);
  EXPECT_LT(std::abs(r.volume_error), 0.01);
  EXPECT_EQ(r.tets, tets.element_count());
  EXPECT_GE(r.quality.min_radius_ratio, 0.05) << r.summary();
  EXPECT_GT(r.quality.min_dihedral, 5.0) << r.summary();
  EXPECT_FALSE(r.surface_preserved);
  EXPECT_GT(r.hausdorff, 0.0);
  EXPECT_LT(r.hausdorff, 0.02 * radius);  // the new surface stays on the old one
  // Every boundary node of the tets lies on the sphere to within the input's chord sag.
  const RowMatXi boundary = boundary_facets(tets);
  for (Eigen::Index f = 0; f < boundary.rows(); ++f)
    EXPECT_NEAR(tets.nodes.row(boundary(f, 0)).norm(), radius, 0.01 * radius);
  EXPECT_NE(r.summary().find("radius ratio min"), std::string::npos);
  // Coarser, the chords cut off more than the 1 % allowed, and the error says what to change.
  o.max_size = radius / 2.0;
  EXPECT_NE(error_of(sphere, o).find("smaller --size"), std::string::npos) << error_of(sphere, o);
}

TEST(Tetrahedralize, KeptCubeSurfaceIsTheBoundaryExactly) {
  const Mesh cube = cube_surface(4, 0.1);
  TetrahedralizeReport r;
  const Mesh tets = tetrahedralize(cube, {}, &r);  // the default keeps the surface
  EXPECT_TRUE(r.surface_preserved);
  EXPECT_EQ(r.hausdorff, 0.0);
  EXPECT_NEAR(r.volume, 1e-3, 1e-15);
  EXPECT_EQ(boundary_facets(tets).rows(), cube.element_count());
  EXPECT_EQ(tets.nodes.topRows(cube.node_count()), cube.nodes);
}

// A segmentation's speck beside the body (a cube of 1/20 the side: 1/8000 of the volume) is dropped by default, and
// reported; with speck_fraction 0 the surface of two pieces is refused as before.
TEST(Tetrahedralize, SpecksAreDroppedAndReported) {
  const Mesh body = cube_surface(4, 0.1);
  Mesh speck = cube_surface(1, 0.005);
  speck.nodes.col(0).array() += 0.2;
  const Mesh both = test::two_pieces(body, speck, "cube and speck");
  TetrahedralizeReport r;
  const Mesh tets = tetrahedralize(both, {}, &r);
  EXPECT_EQ(r.dropped_pieces, 1);
  EXPECT_NEAR(r.dropped_volume, 1.25e-7, 1e-15);
  EXPECT_NEAR(r.volume, 1e-3, 1e-15);
  EXPECT_EQ(r.surface_triangles, body.element_count());
  EXPECT_NE(r.summary().find("1 specks dropped"), std::string::npos) << r.summary();
  TetrahedralizeOptions keep;
  keep.speck_fraction = 0.0;
  EXPECT_NE(error_of(both, keep).find("several separate pieces"), std::string::npos);
  keep.speck_fraction = 2.0;
  EXPECT_THROW(tetrahedralize(both, keep), InvalidArgument);
}

// --repair N closes holes of at most N edges: a cube missing one triangle (a 3-edge hole) or two (a square) meshes to
// the cube's volume with the missing area added back; a hole longer than N is still refused, naming an edge.
TEST(Tetrahedralize, RepairClosesSmallHolesOnly) {
  const Mesh cube = cube_surface(4, 0.1);
  for (const int missing : {1, 2}) {
    Mesh holed = cube;
    holed.elements = cube.elements.bottomRows(cube.element_count() - missing).eval();
    holed.region.setZero(holed.element_count());
    EXPECT_NE(error_of(holed).find("hole"), std::string::npos) << error_of(holed);
    TetrahedralizeOptions o;
    o.repair_max_edges = 8;
    TetrahedralizeReport r;
    tetrahedralize(holed, o, &r);
    EXPECT_EQ(r.closed_holes, 1);
    EXPECT_NEAR(r.added_area, missing * 0.5 * 0.025 * 0.025, 1e-15);  // the missing triangles' area
    EXPECT_NEAR(r.volume, 1e-3, 1e-15);
    EXPECT_NE(r.summary().find("1 holes closed"), std::string::npos) << r.summary();
    o.repair_max_edges = 3;  // the square's 4 edges are too many
    if (missing == 2) {
      EXPECT_NE(error_of(holed, o).find("hole"), std::string::npos);
    }
  }
  TetrahedralizeOptions bad;
  bad.repair_max_edges = 2;
  EXPECT_THROW(tetrahedralize(cube, bad), InvalidArgument);
}

TEST(Tetrahedralize, RefusalsNameTheCause) {
  Mesh hole = cube_surface(3, 1.0);
  hole.elements.conservativeResize(hole.element_count() - 1, 3);
  EXPECT_NE(error_of(hole).find("hole"), std::string::npos) << error_of(hole);
  Mesh dent = cube_surface(4, 1.0);
  for (int i = 0; i < dent.node_count(); ++i)
    if (std::abs(dent.nodes(i, 2) - 1.0) < 1e-12 && std::abs(dent.nodes(i, 0) - 0.5) < 1e-12 &&
        std::abs(dent.nodes(i, 1) - 0.5) < 1e-12)
      dent.nodes.row(i) << 0.52, 0.47, -0.5;  // through the bottom, off its edges
  EXPECT_NE(error_of(dent).find("cross each other"), std::string::npos) << error_of(dent);
  EXPECT_NE(error_of(tet_box(1, 1, 1, 1, 1, 1)).find("closed triangle surface"), std::string::npos);
  TetrahedralizeOptions bad;
  bad.max_size = -1.0;
  EXPECT_THROW(tetrahedralize(cube_surface(2, 1.0), bad), InvalidArgument);
  bad = {};
  bad.min_radius_ratio = 1.5;
  EXPECT_THROW(tetrahedralize(cube_surface(2, 1.0), bad), InvalidArgument);
  // A floor no mesh meets names the worst tet.
  TetrahedralizeOptions strict;
  strict.min_radius_ratio = 0.99;
  EXPECT_NE(error_of(cube_surface(3, 1.0), strict).find("quality floor"), std::string::npos);
  EXPECT_THROW(surface_meshing_from_name("smooth"), InvalidArgument);
  EXPECT_NEAR(edge_of_regular_tet(std::pow(0.1, 3) / (6.0 * std::sqrt(2.0))), 0.1, 1e-15);
  EXPECT_NEAR(regular_tet_volume(0.1), std::pow(0.1, 3) / (6.0 * std::sqrt(2.0)), 1e-18);
  EXPECT_NEAR(edge_of_regular_tet(regular_tet_volume(0.037)), 0.037, 1e-15);
}

TEST(Tetrahedralize, RealFemurScan) {
  const Mesh femur = scan("femur.off");  // 3 897 nodes, genus 2
  TetrahedralizeReport r;
  const Mesh tets = tetrahedralize(femur, {}, &r);
  EXPECT_EQ(r.surface_nodes, 3897);
  EXPECT_TRUE(r.surface_preserved);  // the scan's nodes are the first nodes, unmoved
  EXPECT_EQ(tets.nodes.topRows(femur.node_count()), femur.nodes);
  EXPECT_LT(std::abs(r.volume_error), 1e-9) << r.summary();
  // Reported, not refused by default: a few slivers (below 0.01), most tets well shaped.
  EXPECT_GT(r.quality.mean_radius_ratio, 0.5) << r.summary();
  EXPECT_LT(r.slivers, tets.element_count() / 1000) << r.summary();
  EXPECT_GT(tets.element_count(), 3 * femur.node_count());
  // With a floor, the mesh is refused naming the worst tet.
  TetrahedralizeOptions floor;
  floor.min_radius_ratio = 0.05;
  EXPECT_NE(error_of(femur, floor).find("quality floor"), std::string::npos);
}

TEST(Tetrahedralize, OpenAndSelfCrossingScansAreRefused) {
  const std::string head = error_of(scan("head.off"));  // an open face scan
  EXPECT_NE(head.find("hole"), std::string::npos) << head;
  EXPECT_NE(head.find("head.off"), std::string::npos) << head;
  const std::string bones = error_of(scan("bones.off"));  // two bones, apart and crossing
  EXPECT_NE(bones.find("several separate pieces"), std::string::npos) << bones;
}

}  // namespace
}  // namespace hooke::mesh
