#include <gtest/gtest.h>

#include <hooke/core/error.hpp>
#include <hooke/experiments/load_case.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <support/meshes.hpp>

namespace hooke::experiments {
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

TEST(LoadCase, TractionForStrainGivesTheRequestedMeanDisplacement) {
  const mesh::Mesh cyl = io::read_mesh(HOOKE_MESH_DATA "/cylinder.msh");
  const material::Material mat{material::Law::kLinear, 14630.0, 0.3};
  const double t = traction_for_strain(cyl, {mat}, LoadKind::kStretch, 0.12);
  auto model = std::make_shared<model::Model>(3, test::flat_positions(cyl));
  model->add(fem::make_elastic_block(cyl, mat));
  model::Problem p = model::make_problem(model);
  const LoadCase lc = make_load_case(cyl, LoadKind::kStretch, t);
  apply(lc, p);
  const auto r = solve::linear_static(p);
  EXPECT_NEAR(mean_top_displacement(lc, p, r.positions), 0.12 * 0.02, 1e-12);
  // A stubby clamped cylinder is stiffer than a free bar: more than E * strain is needed.
  EXPECT_GT(t, 0.12 * 14630.0);
  // The response that comes with it (the unit solve scaled) is the linear solve at that traction, report included.
  for (LoadKind kind : {LoadKind::kStretch, LoadKind::kShear}) {
    const StrainResponse s = linear_response_for_strain(cyl, {mat}, kind, 0.12);
    const LoadCase lk = make_load_case(cyl, kind, s.traction_pa);
    model::Problem pk = model::make_problem(model);
    apply(lk, pk);
    const auto rk = solve::linear_static(pk);
    EXPECT_LT((s.fem.positions - rk.positions).norm(), 1e-10 * (rk.positions - model->rest_positions()).norm());
    EXPECT_NEAR(s.fem.report.reference_force, rk.report.reference_force, 1e-12 * rk.report.reference_force);
    EXPECT_EQ(s.fem.report.status, solve::SolveStatus::kConverged);
  }
  EXPECT_EQ(linear_response_for_strain(cyl, {mat}, LoadKind::kStretch, 0.12).traction_pa, t);
  // All three kinds from one factorisation: the single responses.
  const std::vector<LoadKind> kinds{LoadKind::kStretch, LoadKind::kCompress, LoadKind::kShear};
  const std::vector<StrainResponse> all = linear_responses_for_strain(cyl, {mat}, kinds, 0.12);
  ASSERT_EQ(all.size(), 3u);
  for (size_t k = 0; k < kinds.size(); ++k) {
    const StrainResponse one = linear_response_for_strain(cyl, {mat}, kinds[k], 0.12);
    EXPECT_NEAR(all[k].traction_pa, one.traction_pa, 1e-12 * one.traction_pa);
    EXPECT_LT((all[k].fem.positions - one.fem.positions).norm(),
              1e-12 * (one.fem.positions - model->rest_positions()).norm());
  }
  // Compression is stretch reversed (the same supports and the opposite forces): the same traction.
  EXPECT_NEAR(all[1].traction_pa, all[0].traction_pa, 1e-12 * all[0].traction_pa);
}

TEST(LoadCase, MeshWithoutFlatTopIsRejected) {
  const mesh::Mesh surface = mesh::cube_surface(2, 1.0);
  EXPECT_THROW(make_load_case(surface, LoadKind::kStretch, 1.0), InvalidArgument);
}

}  // namespace
}  // namespace hooke::experiments
