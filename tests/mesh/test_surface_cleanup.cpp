// mesh/surface_cleanup: welding a cracked surface, dropping a speck, Taubin smoothing without shrinking.
#include <gtest/gtest.h>

#include <support/meshes.hpp>

#include <cmath>
#include <hooke/mesh/closed_surface.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/surface_cleanup.hpp>

namespace hooke::mesh {
namespace {

// `m` with every triangle given its own three nodes (a marching-cubes output before welding).
Mesh cracked(const Mesh& m) {
  RowMatX x(3 * m.element_count(), 3);
  RowMatXi t(m.element_count(), 3);
  for (int e = 0; e < m.element_count(); ++e)
    for (int k = 0; k < 3; ++k) {
      x.row(3 * e + k) = m.nodes.row(m.elements(e, k));
      t(e, k) = 3 * e + k;
    }
  return make_mesh(ElementKind::kSurfaceTriangle, x, t, "cracked");
}

TEST(SurfaceCleanup, WeldsACrackedSurfaceBackToTheClosedOne) {
  const Mesh cube = cube_surface(3, 0.01);
  int merged = 0;
  Mesh welded = weld_surface(cracked(cube), &merged);
  EXPECT_EQ(welded.node_count(), cube.node_count());
  EXPECT_EQ(welded.element_count(), cube.element_count());
  EXPECT_EQ(merged, 3 * cube.element_count() - cube.node_count());
  EXPECT_NEAR(check_closed_surface(welded).volume, 1e-6, 1e-15);
  // a doubled triangle (a sheet of no thickness) and a degenerate one are removed
  Mesh extra = cube;
  extra.elements.conservativeResize(cube.element_count() + 2, 3);
  extra.elements.row(cube.element_count()) = cube.elements.row(0).reverse();
  extra.elements.row(cube.element_count() + 1) << 0, 0, 1;
  extra.region.setZero(extra.element_count());
  EXPECT_EQ(weld_surface(extra).element_count(), cube.element_count() - 1);
}

TEST(SurfaceCleanup, DropsASpeckAndKeepsTheBody) {
  const Mesh body = uv_sphere_surface(12, 16, 0.01);
  Mesh speck = uv_sphere_surface(6, 8, 0.001);
  speck.nodes.col(0).array() += 0.05;
  const Mesh both = test::two_pieces(body, speck, "two pieces");
  PiecesReport r;
  const Mesh kept = drop_small_pieces(both, 1e-2, &r);
  EXPECT_EQ(r.pieces, 2);
  EXPECT_EQ(r.dropped, 1);
  EXPECT_EQ(kept.element_count(), body.element_count());
  EXPECT_GT(r.dropped_volume, 0.0);
  EXPECT_LT(r.dropped_volume, 1e-3 * r.kept_volume);
  EXPECT_EQ(drop_small_pieces(both, 1e-4, &r).element_count(), both.element_count());  // the speck is 1e-3
}

TEST(SurfaceCleanup, TaubinSmoothingFlattensNoiseWithoutShrinking) {
  Mesh sphere = uv_sphere_surface(16, 24, 0.01);
  const double v0 = check_closed_surface(sphere).volume;
  Mesh noisy = sphere;
  for (int i = 0; i < noisy.node_count(); ++i) noisy.nodes.row(i) *= 1.0 + 0.03 * std::sin(37.0 * i);
  auto roughness = [](const Mesh& m) {  // RMS deviation of the node radii from their mean
    VecX r(m.node_count());
    for (int i = 0; i < m.node_count(); ++i) r(i) = m.nodes.row(i).norm();
    return std::sqrt((r.array() - r.mean()).square().mean());
  };
  Mesh smooth = noisy;
  taubin_smooth(smooth, 10);
  EXPECT_LT(roughness(smooth), 0.5 * roughness(noisy));
  EXPECT_LT(std::abs(check_closed_surface(smooth).volume / v0 - 1.0), 0.02);
  taubin_smooth(sphere, 0);
  EXPECT_EQ(sphere.nodes, uv_sphere_surface(16, 24, 0.01).nodes);  // no iterations: unchanged
}

}  // namespace
}  // namespace hooke::mesh
