#include <gtest/gtest.h>

#include <hooke/core/error.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/model/load_case.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <hooke/solve/strain_response.hpp>
#include <support/meshes.hpp>

namespace hooke::solve {
namespace {

TEST(LoadCase, TractionForStrainGivesTheRequestedMeanDisplacement) {
  const mesh::Mesh cyl = io::read_mesh(HOOKE_MESH_DATA "/cylinder.msh");
  const material::Material mat{material::Law::kLinear, 14630.0, 0.3};
  const double t = traction_for_strain(cyl, {mat}, model::LoadKind::kStretch, 0.12);
  auto linear = std::make_shared<model::Model>(3, test::flat_positions(cyl));
  linear->add(fem::make_elastic_block(cyl, mat));
  model::Problem p = model::make_problem(linear);
  const model::LoadCase lc = model::make_load_case(cyl, model::LoadKind::kStretch, t);
  apply(lc, p);
  const auto r = linear_static(p);
  EXPECT_NEAR(model::mean_top_displacement(lc, p, r.positions), 0.12 * 0.02, 1e-12);
  // A stubby clamped cylinder is stiffer than a free bar: more than E * strain is needed.
  EXPECT_GT(t, 0.12 * 14630.0);
  // The response that comes with it (the unit solve scaled) is the linear solve at that traction, report included.
  for (model::LoadKind kind : {model::LoadKind::kStretch, model::LoadKind::kShear}) {
    const StrainResponse s = linear_response_for_strain(cyl, {mat}, kind, 0.12);
    const model::LoadCase lk = model::make_load_case(cyl, kind, s.traction_pa);
    model::Problem pk = model::make_problem(linear);
    apply(lk, pk);
    const auto rk = linear_static(pk);
    EXPECT_LT((s.fem.positions - rk.positions).norm(), 1e-10 * (rk.positions - linear->rest_positions()).norm());
    EXPECT_NEAR(s.fem.report.reference_force, rk.report.reference_force, 1e-12 * rk.report.reference_force);
    EXPECT_EQ(s.fem.report.status, SolveStatus::kConverged);
  }
  EXPECT_EQ(linear_response_for_strain(cyl, {mat}, model::LoadKind::kStretch, 0.12).traction_pa, t);
  // All three kinds from one factorisation: the single responses.
  const std::vector<model::LoadKind> kinds{model::LoadKind::kStretch, model::LoadKind::kCompress,
                                           model::LoadKind::kShear};
  const std::vector<StrainResponse> all = linear_responses_for_strain(cyl, {mat}, kinds, 0.12);
  ASSERT_EQ(all.size(), 3u);
  for (size_t k = 0; k < kinds.size(); ++k) {
    const StrainResponse one = linear_response_for_strain(cyl, {mat}, kinds[k], 0.12);
    EXPECT_NEAR(all[k].traction_pa, one.traction_pa, 1e-12 * one.traction_pa);
    EXPECT_LT((all[k].fem.positions - one.fem.positions).norm(),
              1e-12 * (one.fem.positions - linear->rest_positions()).norm());
  }
  // Compression is stretch reversed (the same supports and the opposite forces): the same traction.
  EXPECT_NEAR(all[1].traction_pa, all[0].traction_pa, 1e-12 * all[0].traction_pa);
}

}  // namespace
}  // namespace hooke::solve
