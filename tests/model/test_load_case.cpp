#include <gtest/gtest.h>

#include <hooke/core/error.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/model/load_case.hpp>
#include <hooke/solve/static_equilibrium.hpp>
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

// Displacement control on the linear FEM, checked by two identities independent of top_reaction's sum: in
// equilibrium the strain energy is half the work of the top's force over its rigid move, E = R . (delta d) / 2,
// and the force is linear in the move. Under traction control the same sum is the applied load.
TEST(LoadCase, DisplacementControlReactionIsTheWorkConjugateOfTheMove) {
  const mesh::Mesh cyl = io::read_mesh(HOOKE_MESH_DATA "/cylinder.msh");
  const auto fem = fem::elastic_model(cyl, {{material::Law::kLinear, 14630.0, 0.3}}, material::Law::kLinear);
  for (LoadKind k : {LoadKind::kStretch, LoadKind::kCompress, LoadKind::kShear}) {
    VecX reactions[2];
    for (int scale : {1, 2}) {
      const LoadCase lc = make_displacement_case(cyl, k, 1e-4 * scale);
      EXPECT_EQ(lc.control, LoadControl::kDisplacement);
      EXPECT_EQ(lc.nodal_forces.norm(), 0.0);
      Problem p = make_problem(fem);
      apply(lc, p);
      const solve::StaticResult r = solve::linear_static(p);
      ASSERT_EQ(r.report.status, solve::SolveStatus::kConverged);
      EXPECT_NEAR(mean_top_displacement(lc, p, r.positions), 1e-4 * scale, 1e-15);
      const VecX reaction = top_reaction(lc, p, r.positions);
      const double work = reaction.dot(lc.displacement * lc.direction);
      EXPECT_NEAR(fem->energy(r.positions), 0.5 * work, 1e-9 * work) << load_kind_name(k);
      EXPECT_GT(reaction.dot(lc.direction), 0.0);  // the body pushes back against the move
      reactions[scale - 1] = reaction;
    }
    EXPECT_LT((reactions[1] - 2.0 * reactions[0]).norm(), 1e-9 * reactions[1].norm());
  }
  const LoadCase traction = make_load_case(cyl, LoadKind::kStretch, 300.0);
  Problem p = make_problem(fem);
  apply(traction, p);
  const solve::StaticResult r = solve::linear_static(p);
  EXPECT_LT((top_reaction(traction, p, r.positions) - 300.0 * traction.top_area * Vec3(0, 0, 1)).norm(),
            1e-8 * 300.0 * traction.top_area);
  EXPECT_EQ(load_control_from_name("displacement"), LoadControl::kDisplacement);
  EXPECT_THROW(load_control_from_name("force"), InvalidArgument);
  EXPECT_THROW(make_displacement_case(cyl, LoadKind::kStretch, std::nan("")), InvalidArgument);
}

// A nonlinear solve ramps the prescribed move with the load factor: a 40 % press of the Neo-Hookean FEM reaches a
// stable equilibrium in load steps, with the top exactly where it was put.
TEST(LoadCase, RampedPressOfTheNonlinearFemConverges) {
  const mesh::Mesh cyl = io::read_mesh(HOOKE_MESH_DATA "/cylinder.msh");
  const auto fem = fem::elastic_model(cyl, {{material::Law::kNeoHookean, 14630.0, 0.45}}, material::Law::kNeoHookean);
  const LoadCase lc = make_displacement_case(cyl, LoadKind::kCompress, 0.4 * 0.02);
  Problem p = make_problem(fem);
  apply(lc, p);
  solve::StaticOptions o;
  o.ramp_prescribed = true;
  const solve::StaticResult r = solve::static_equilibrium(p, o);
  ASSERT_EQ(r.report.status, solve::SolveStatus::kConverged) << r.report.message;
  EXPECT_NEAR(mean_top_displacement(lc, p, r.positions), 0.008, 1e-12);
  EXPECT_GT(r.report.min_eigenvalue, 0.0);
}

TEST(LoadCase, MeshWithoutFlatTopIsRejected) {
  const mesh::Mesh surface = mesh::cube_surface(2, 1.0);
  EXPECT_THROW(make_load_case(surface, LoadKind::kStretch, 1.0), InvalidArgument);
}

}  // namespace
}  // namespace hooke::model
