// The radial discretisation (Arnab & Raja Fig. 5, 6) and the mass estimation ratio: masses sum to M for any
// mesh and after a local refinement; the per-node volumes are exact on a cube.
#include <gtest/gtest.h>

#include <hooke/mesh/closed_surface.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/surface/discretisation.hpp>
#include <hooke/surface/refine.hpp>

namespace hooke::surface {
namespace {

Discretisation of(mesh::Mesh& m) {
  mesh::check_closed_surface(m);
  return discretise(m, mesh::volume_centroid(m));
}

TEST(Discretisation, RadialVolumesCountEachConeThreeTimes) {
  for (mesh::Mesh m : {mesh::cube_surface(5, 0.1), mesh::uv_sphere_surface(12, 20, 0.05)}) {
    const Discretisation d = of(m);
    EXPECT_NEAR(d.radial_volume.sum(), 3.0 * d.volume, 1e-12 * d.volume);
    EXPECT_GT(d.normal_length.minCoeff(), 0.0);
    EXPECT_LE((d.normal_length - d.radial_length).maxCoeff(), 1e-15);  // L' <= L
  }
}

// On a cube face every node's axis is the face's distance to the centre, and its Fig. 6 volume is its face area
// share times that distance (each adjacent cone counted whole: A_i L' with A_i = sum_t A_t / 3 x 3).
TEST(Discretisation, FaceNodesOfACubeSeeTheFaceDistance) {
  mesh::Mesh m = mesh::cube_surface(4, 2.0);
  const Discretisation d = of(m);
  for (int i = 0; i < m.node_count(); ++i) {
    const Vec3 p = m.nodes.row(i).transpose();
    const int on_faces = (p.array() < 1e-12 || p.array() > 2.0 - 1e-12).count();
    if (on_faces != 1) continue;  // edges and corners have averaged normals
    EXPECT_NEAR(d.normal_length(i), 1.0, 1e-14);
    EXPECT_NEAR(d.normal_volume(i), 6 * 0.5 * 0.5 * 0.5 / 3.0 * 1.0, 1e-14);  // six triangles of area 1/8
  }
}

TEST(Discretisation, MassesSumToTheObjectMassAlsoAfterRefinement) {
  mesh::Mesh sphere = mesh::uv_sphere_surface(10, 16, 0.05);
  const Discretisation d = of(sphere);
  const VecX m = estimated_masses(d, 0.7);
  EXPECT_NEAR(m.sum(), 0.7, 1e-14);
  EXPECT_GT(m.minCoeff(), 0.0);
  mesh::Mesh refined = refine_near(sphere, Vec3(0.0, 0.0, 0.05), 0.02);
  EXPECT_GT(refined.node_count(), sphere.node_count());
  const Discretisation dr = of(refined);
  EXPECT_NEAR(dr.volume, d.volume, 1e-12 * d.volume);  // midpoints stay on the flat edges
  const VecX mr = estimated_masses(dr, 0.7);
  EXPECT_NEAR(mr.sum(), 0.7, 1e-14);
  // Away from the refinement the masses are unchanged; inside they are smaller (more nodes share the volume).
  const int far = sphere.node_count() - 1;  // the south pole
  EXPECT_NEAR(mr(far), m(far), 1e-12);
  EXPECT_LT(mr(0), m(0));  // the north pole, in the refined area
}

TEST(Discretisation, DepthReadingMatchesTheRadialOneWhereBothApply) {
  // A sphere about the origin: the inward ray from a node meets the far side at 2 R (less the chords' sag), so
  // L'_i = R as the radial reading from the centre gives; a cube's face nodes see the opposite face at its edge.
  mesh::Mesh sphere = mesh::uv_sphere_surface(16, 24, 0.05);
  mesh::check_closed_surface(sphere);
  const Discretisation radial = discretise(sphere, Vec3::Zero()), depth = discretise_by_depth(sphere);
  for (int i = 0; i < sphere.node_count(); ++i) {
    EXPECT_NEAR(depth.normal_length(i), radial.normal_length(i), 0.01 * 0.05) << i;
    EXPECT_NEAR(depth.normal_volume(i), radial.normal_volume(i), 0.05 * radial.normal_volume(i)) << i;
  }
  EXPECT_DOUBLE_EQ(depth.volume, radial.volume);
  mesh::Mesh cube = mesh::cube_surface(4, 1.0);
  mesh::check_closed_surface(cube);
  const Discretisation c = discretise_by_depth(cube);
  for (int i = 0; i < cube.node_count(); ++i) {
    const Vec3 p = cube.nodes.row(i).transpose();
    const bool face_interior = ((p.array() > 1e-9) && (p.array() < 1.0 - 1e-9)).count() == 2;
    if (face_interior) {
      EXPECT_NEAR(c.normal_length(i), 0.5, 1e-12) << i;
    }
  }
}

TEST(Discretisation, DepthReadingServesASurfaceThatIsNotStarShaped) {
  // A cube with its top centre pushed deep inside: not star-shaped from the centre (StarShape test), yet every
  // node's inner point lies inside the body, below its own triangles.
  mesh::Mesh dent = mesh::cube_surface(4, 1.0);
  for (int i = 0; i < dent.node_count(); ++i)
    if (std::abs(dent.nodes(i, 2) - 1.0) < 1e-12 && std::abs(dent.nodes(i, 0) - 0.5) < 1e-12 &&
        std::abs(dent.nodes(i, 1) - 0.5) < 1e-12)
      dent.nodes(i, 2) = 0.3;
  mesh::check_closed_surface(dent);
  const Discretisation d = discretise_by_depth(dent);
  EXPECT_GT(d.normal_length.minCoeff(), 0.0);
  EXPECT_GT(d.normal_volume.minCoeff(), 0.0);
  for (int i = 0; i < dent.node_count(); ++i) {
    const Vec3 ci = dent.nodes.row(i).transpose() - d.normal_length(i) * d.normals.row(i).transpose();
    EXPECT_TRUE((ci.array() > 0.0).all() && (ci.array() < 1.0).all()) << i << ": " << ci.transpose();
  }
  EXPECT_NEAR(estimated_masses(d, 2.0).sum(), 2.0, 1e-13);
}

TEST(Refine, ClosesConformingly) {
  mesh::Mesh cube = mesh::cube_surface(4, 1.0);
  mesh::Mesh r = refine_near(cube, Vec3(0.5, 0.5, 1.0), 0.3);
  EXPECT_NO_THROW(mesh::check_closed_surface(r));  // closed and manifold: no hanging nodes
  EXPECT_GT(r.element_count(), cube.element_count());
  EXPECT_EQ(refine_near(cube, Vec3(5, 5, 5), 0.1).element_count(), cube.element_count());
}

}  // namespace
}  // namespace hooke::surface
