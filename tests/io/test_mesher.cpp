// TetGen's program as a volume mesher (io::volume_mesher): the kept cube and a real femur scan bounded by their own
// triangles, the same report as Netgen's, and the refusals (not installed, its failure, remeshing, the mesh layer
// asked to run a program).
#include <gtest/gtest.h>
#include <stdlib.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <hooke/core/error.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/io/mesher.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/mesh/topology.hpp>
#include <string>

namespace hooke::io {
namespace {

mesh::TetrahedralizeOptions tetgen() {
  mesh::TetrahedralizeOptions o;
  o.mesher = mesh::Mesher::kTetgen;
  return o;
}

std::string error_of(const mesh::Mesh& surface, const mesh::TetrahedralizeOptions& o) {
  try {
    io::tetrahedralize(surface, o);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// Sets PATH for the life of the object (the spawned mesher is looked up on it).
class ScopedPath {
 public:
  explicit ScopedPath(const std::string& path) : m_old(std::getenv("PATH") ? std::getenv("PATH") : "") {
    setenv("PATH", path.c_str(), 1);
  }
  ~ScopedPath() { setenv("PATH", m_old.c_str(), 1); }
  ScopedPath(const ScopedPath&) = delete;
  ScopedPath& operator=(const ScopedPath&) = delete;

 private:
  std::string m_old;
};

TEST(TetgenMesher, KeptCubeSurfaceIsTheBoundaryExactly) {
  const mesh::Mesh cube = mesh::cube_surface(4, 0.1);
  mesh::TetrahedralizeReport r;
  const mesh::Mesh tets = io::tetrahedralize(cube, tetgen(), &r);
  EXPECT_NE(r.backend.find("tetgen"), std::string::npos) << r.backend;
  EXPECT_TRUE(r.surface_preserved) << r.summary();
  EXPECT_EQ(tets.nodes.topRows(cube.node_count()), cube.nodes);
  EXPECT_EQ(r.hausdorff, 0.0);
  EXPECT_NEAR(r.volume, 1e-3, 1e-15);
  EXPECT_EQ(mesh::boundary_facets(tets).rows(), cube.element_count());
  for (int e = 0; e < tets.element_count(); ++e) ASSERT_GT(mesh::element_measure(tets, e), 0.0) << e;
  // The cube's 0.025 m triangles are kept while the inside is meshed at diagonal / 25 = 0.007 m: no sliver.
  EXPECT_EQ(r.slivers, 0) << r.summary();
  EXPECT_GT(r.quality.mean_radius_ratio, 0.6) << r.summary();
  EXPECT_EQ(r.summary().find("grading"), std::string::npos) << r.summary();  // Netgen's parameters are not TetGen's
}

TEST(TetgenMesher, RealFemurScanKeepsItsNodesAndVolume) {
  const std::filesystem::path path = std::filesystem::path(HOOKE_SCAN_DATA) / "femur.off";
  if (!std::filesystem::exists(path))
    throw IoError(path.string() + " is missing: scripts/setup.sh installs it (Debian package libcgal-demo)");
  const mesh::Mesh femur = read_mesh(path);  // 3 897 nodes, genus 2
  mesh::TetrahedralizeReport r;
  const mesh::Mesh tets = io::tetrahedralize(femur, tetgen(), &r);
  EXPECT_TRUE(r.surface_preserved);
  EXPECT_EQ(tets.nodes.topRows(femur.node_count()), femur.nodes);
  EXPECT_LT(std::abs(r.volume_error), 1e-9) << r.summary();
  EXPECT_GT(r.quality.mean_radius_ratio, 0.5) << r.summary();
  EXPECT_LT(r.slivers, tets.element_count() / 1000) << r.summary();
  EXPECT_GT(tets.element_count(), 3 * femur.node_count());
  EXPECT_NE(tets.source.find("femur.off"), std::string::npos) << tets.source;
}

TEST(TetgenMesher, RefusalsNameTheCause) {
  const mesh::Mesh cube = mesh::cube_surface(2, 1.0);
  mesh::TetrahedralizeOptions remesh = tetgen();
  remesh.surface = mesh::SurfaceMeshing::kRemesh;
  EXPECT_NE(error_of(cube, remesh).find("Netgen's"), std::string::npos) << error_of(cube, remesh);
  // The mesh layer runs no program: it says where that is done.
  EXPECT_THROW(mesh::tetrahedralize(cube, tetgen()), InvalidArgument);
  EXPECT_THROW(mesh::mesher_from_name("gmsh"), InvalidArgument);
  EXPECT_EQ(mesh::mesher_from_name("tetgen"), mesh::Mesher::kTetgen);
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / "hooke_fake_tetgen";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  {
    ScopedPath empty(dir.string());  // no tetgen on it
    const std::string missing = error_of(cube, tetgen());
    EXPECT_NE(missing.find("scripts/setup.sh installs it"), std::string::npos) << missing;
  }
  // A tetgen that fails: its own last words and its exit status reach the error.
  {
    std::ofstream script(dir / "tetgen");
    script << "#!/bin/sh\necho 'Error:  A segment and a facet intersect at point'\nexit 3\n";
  }
  std::filesystem::permissions(dir / "tetgen", std::filesystem::perms::owner_all);
  ScopedPath fake(dir.string() + ":/usr/bin:/bin");
  const std::string failed = error_of(cube, tetgen());
  EXPECT_NE(failed.find("exit status 3"), std::string::npos) << failed;
  EXPECT_NE(failed.find("A segment and a facet intersect"), std::string::npos) << failed;
}

}  // namespace
}  // namespace hooke::io
