// Newton on the total potential: agreement with the linear solve at tiny loads, invariance under rigid
// rotation, detection of buckling (never returning the unstable symmetric state), clear failures.
#include <gtest/gtest.h>

#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/model/load_case.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <iostream>
#include <support/meshes.hpp>

namespace hooke::solve {
namespace {

using material::Law;
using model::LoadKind;

model::Problem loaded(const mesh::Mesh& m, Law law, model::LoadKind kind, double traction, double thickness = 0.01) {
  auto model = std::make_shared<model::Model>(m.dim(), test::flat_positions(m));
  model->add(fem::make_elastic_block(m, {law, 14630.0, 0.3, material::Plane::kStress, thickness}));
  model::Problem p = model::make_problem(model);
  model::apply(model::make_load_case(m, kind, traction, thickness), p);
  return p;
}

const mesh::Mesh& column3d() {
  static const mesh::Mesh m = test::perturb_interior(mesh::tet_box(0.01, 0.01, 0.02, 3, 3, 6), 0.2);
  return m;
}

TEST(StaticEquilibrium, NonlinearLawsAgreeWithLinearForTinyLoads) {
  for (model::LoadKind kind : {model::LoadKind::kStretch, model::LoadKind::kCompress, model::LoadKind::kShear}) {
    const auto lin = linear_static(loaded(column3d(), Law::kLinear, kind, 0.05));
    require_converged(lin.report);
    const VecX u_lin = lin.positions - test::flat_positions(column3d());
    for (Law law : {Law::kStVK, Law::kNeoHookean}) {
      const auto r = static_equilibrium(loaded(column3d(), law, kind, 0.05));
      require_converged(r.report);
      const VecX u = r.positions - test::flat_positions(column3d());
      EXPECT_LT((u - u_lin).norm(), 1e-4 * u_lin.norm()) << material::law_name(law);
    }
  }
}

TEST(StaticEquilibrium, LinearLawNewtonEqualsLinearSolve) {
  const auto lin = linear_static(loaded(column3d(), Law::kLinear, model::LoadKind::kShear, 800.0));
  const auto newton = static_equilibrium(loaded(column3d(), Law::kLinear, model::LoadKind::kShear, 800.0));
  require_converged(newton.report);
  EXPECT_LT((lin.positions - newton.positions).norm(), 1e-8 * lin.positions.norm());
  EXPECT_LE(newton.report.iterations, 2 * newton.report.load_steps);
}

// Modified Newton that solves the current Newton system by CG preconditioned with its kept factorisation before it
// refactorises (NewtonOptions::reuse_krylov_iterations): the same equilibria of a NeoHookean column at a load
// where the tangent moves from the rest one, with fewer factorisations than plain modified Newton.
TEST(StaticEquilibrium, KeptFactorPreconditionedStepsGiveTheSameStatesWithFewerFactorisations) {
  int plain_total = 0, krylov_total = 0;
  for (model::LoadKind kind : {model::LoadKind::kStretch, model::LoadKind::kCompress, model::LoadKind::kShear}) {
    const model::Problem p = loaded(column3d(), Law::kNeoHookean, kind, 700.0);
    StaticOptions o;
    o.newton.reuse_factorization = true;
    o.estimate_min_eigenvalue = false;
    o.initial_load_steps = 1;
    const StaticResult plain = static_equilibrium(p, o);
    o.newton.reuse_krylov_iterations = 20;
    const StaticResult krylov = static_equilibrium(p, o);
    require_converged(plain.report);
    require_converged(krylov.report);
    const VecX u = plain.positions - p.model->rest_positions();
    EXPECT_LT((krylov.positions - plain.positions).norm(), 1e-8 * u.norm()) << model::load_kind_name(kind);
    EXPECT_LE(krylov.report.factorizations, plain.report.factorizations) << model::load_kind_name(kind);
    EXPECT_GE(krylov.report.factorizations, 2);  // the start's, and the final state's stability test
    plain_total += plain.report.factorizations;
    krylov_total += krylov.report.factorizations;
    std::cout << model::load_kind_name(kind) << ": factorisations " << plain.report.factorizations << " -> "
              << krylov.report.factorizations << ", Newton iterations " << plain.report.iterations << " -> "
              << krylov.report.iterations << ", max displacement " << u.cwiseAbs().maxCoeff() << " m\n";
  }
  EXPECT_LT(krylov_total, plain_total);
}

// Several loads on one problem (static_equilibria, linear_statics): the states of separate solves, with modified
// Newton's factorisation carried from load to load, and fewer factorisations in all. Stretch, compression and shear
// clamp the same nodes; a NeoHookean column at a load where Newton needs several iterations.
TEST(StaticEquilibrium, SeveralLoadsOnOneProblemGiveTheSeparateSolvesStates) {
  const std::vector<model::LoadKind> kinds{model::LoadKind::kStretch, model::LoadKind::kCompress,
                                           model::LoadKind::kShear};
  for (Law law : {Law::kLinear, Law::kNeoHookean}) {
    std::vector<VecX> loads;
    std::vector<StaticResult> separate, linear_separate;
    StaticOptions o;
    o.newton.reuse_factorization = true;
    o.estimate_min_eigenvalue = false;
    o.initial_load_steps = 1;
    for (model::LoadKind kind : kinds) {
      const model::Problem p = loaded(column3d(), law, kind, 300.0);
      loads.push_back(p.external_force);
      separate.push_back(static_equilibrium(p, o));
      if (law == Law::kLinear) linear_separate.push_back(linear_static(p));
    }
    const model::Problem p = loaded(column3d(), law, model::LoadKind::kStretch, 300.0);
    const std::vector<StaticResult> together = static_equilibria(p, loads, o);
    ASSERT_EQ(together.size(), kinds.size());
    double separate_seconds = 0.0, together_seconds = 0.0;
    for (size_t k = 0; k < kinds.size(); ++k) {
      require_converged(together[k].report);
      const VecX u = separate[k].positions - p.model->rest_positions();
      EXPECT_LT((together[k].positions - separate[k].positions).norm(), 1e-8 * u.norm()) << k;
      EXPECT_EQ(together[k].report.reference_force, separate[k].report.reference_force);
      EXPECT_GE(together[k].report.iterations, 1);
      separate_seconds += separate[k].report.factorization_seconds;
      together_seconds += together[k].report.factorization_seconds;
    }
    std::cout << "[" << material::law_name(law) << "] factorisation time: separate " << separate_seconds
              << " s, together " << together_seconds << " s\n";
    if (law == Law::kLinear) {
      const std::vector<StaticResult> lin = linear_statics(p, loads);
      for (size_t k = 0; k < kinds.size(); ++k) {
        EXPECT_LT((lin[k].positions - linear_separate[k].positions).norm(),
                  1e-12 * (linear_separate[k].positions - p.model->rest_positions()).norm());
        EXPECT_EQ(lin[k].report.status, SolveStatus::kConverged);
        EXPECT_NEAR(lin[k].report.residual, linear_separate[k].report.residual, 1e-9 * lin[k].report.reference_force);
      }
    }
  }
  // An unheld body: every load reports singular, from the one test of the start.
  const model::Problem held = loaded(column3d(), Law::kLinear, model::LoadKind::kStretch, 300.0);
  model::Problem free_body = model::make_problem(held.model);
  for (const StaticResult& r : static_equilibria(free_body, {held.external_force, -held.external_force}))
    EXPECT_EQ(r.report.status, SolveStatus::kSingular);
  StaticOptions guessed;
  guessed.start = held.model->rest_positions();
  EXPECT_THROW(static_equilibria(held, {held.external_force, held.external_force}, guessed), InvalidArgument);
  EXPECT_THROW(static_equilibria(held, {VecX::Zero(3)}), InvalidArgument);
}

// An initial guess near the answer replaces load stepping (one load step, few iterations, the same state);
// a useless guess (far off) falls back to load stepping from rest; a wrong size is an error.
TEST(StaticEquilibrium, InitialGuessIsUsedWhenItConverges) {
  const model::Problem p = loaded(column3d(), Law::kNeoHookean, model::LoadKind::kStretch, 400.0);
  const auto plain = static_equilibrium(p);
  require_converged(plain.report);
  StaticOptions o;
  o.start = plain.positions + VecX::Constant(plain.positions.size(), 1e-7);
  const auto warm = static_equilibrium(p, o);
  require_converged(warm.report);
  EXPECT_EQ(warm.report.load_steps, 1);
  EXPECT_LT(warm.report.iterations, plain.report.iterations);
  EXPECT_LT((warm.positions - plain.positions).norm(), 1e-9 * plain.positions.norm());
  o.start = VecX::Constant(plain.positions.size(), std::nan(""));
  const auto fallback = static_equilibrium(p, o);
  require_converged(fallback.report);
  EXPECT_LT((fallback.positions - plain.positions).norm(), 1e-9 * plain.positions.norm());
  o.start = VecX::Zero(3);
  EXPECT_THROW(static_equilibrium(p, o), InvalidArgument);
}

TEST(StaticEquilibrium, InvariantUnderRigidRotationOfMeshAndLoad) {
  const mesh::Mesh& m = column3d();
  const Mat3 r = test::random_rotation(4);
  for (Law law : {Law::kStVK, Law::kNeoHookean}) {
    model::Problem p = loaded(m, law, model::LoadKind::kShear, 200.0);
    const auto base = static_equilibrium(p);
    require_converged(base.report);
    mesh::Mesh rotated = m;
    for (int i = 0; i < m.node_count(); ++i) rotated.nodes.row(i) = (r * m.nodes.row(i).transpose()).transpose();
    auto model = std::make_shared<model::Model>(3, test::flat_positions(rotated));
    model->add(fem::make_elastic_block(rotated, {law, 14630.0, 0.3}));
    model::Problem pr = model::make_problem(model);
    pr.fixed_dofs = p.fixed_dofs;
    pr.external_force = p.external_force;
    for (int i = 0; i < m.node_count(); ++i)
      pr.external_force.segment<3>(3 * i) = r * p.external_force.segment<3>(3 * i);
    const auto rot = static_equilibrium(pr);
    require_converged(rot.report);
    double worst = 0;
    for (int i = 0; i < m.node_count(); ++i)
      worst = std::max(worst, (rot.positions.segment<3>(3 * i) - r * base.positions.segment<3>(3 * i)).norm());
    EXPECT_LT(worst, 1e-9) << material::law_name(law);
  }
}

// A slender plane-stress column (W = 1 cm, L = 10 cm), clamped at the bottom, dead load on its free top.
// Euler: sigma_cr = pi^2 E W^2 / (48 L^2) for a clamped-free column. The mesh is mirror-symmetric, so
// Newton follows the straight (symmetric) branch, which is unstable past the critical load.
TEST(StaticEquilibrium, DetectsBucklingAndNeverReturnsTheUnstableState) {
  const mesh::Mesh m = mesh::rectangle_quads(0.01, 0.1, 4, 40);
  const double sigma_cr = M_PI * M_PI * 14630.0 * 0.01 * 0.01 / (48.0 * 0.1 * 0.1);
  const auto below = static_equilibrium(loaded(m, Law::kStVK, model::LoadKind::kCompress, 0.5 * sigma_cr));
  EXPECT_EQ(below.report.status, SolveStatus::kConverged) << below.report.message;
  EXPECT_GT(below.report.min_eigenvalue, 0.0);

  const auto beyond = static_equilibrium(loaded(m, Law::kStVK, model::LoadKind::kCompress, 2.0 * sigma_cr));
  std::cout << "[buckling] " << beyond.report.message
            << "; discrete/analytic critical stress = " << 2.0 * beyond.report.critical_load_factor << "\n";
  ASSERT_EQ(beyond.report.status, SolveStatus::kUnstable) << beyond.report.message;
  EXPECT_GT(beyond.report.critical_load_factor, 0.4);  // Q4 is stiff in bending: it over- rather than under-estimates
  EXPECT_LT(beyond.report.critical_load_factor, 0.75);
  EXPECT_LT(beyond.report.load_factor, beyond.report.critical_load_factor);
  EXPECT_GE(beyond.report.min_eigenvalue, 0.0) << "the returned state must be stable";
  EXPECT_THROW(require_converged(beyond.report), SolverFailure);
}

TEST(StaticEquilibrium, UnheldBodyIsReportedSingular) {
  const mesh::Mesh& m = column3d();
  auto model = std::make_shared<model::Model>(3, test::flat_positions(m));
  model->add(fem::make_elastic_block(m, {Law::kStVK, 14630.0, 0.3}));
  const model::Problem free_body = model::make_problem(model);
  EXPECT_EQ(static_equilibrium(free_body).report.status, SolveStatus::kSingular);
  EXPECT_EQ(linear_static(free_body).report.status, SolveStatus::kSingular);
}

TEST(StaticEquilibrium, ReportsNonConvergence) {
  StaticOptions o;
  o.newton.max_iterations = 1;
  o.initial_load_steps = 1;
  o.min_load_step = 0.3;
  const auto r = static_equilibrium(loaded(column3d(), Law::kNeoHookean, model::LoadKind::kStretch, 3000.0), o);
  EXPECT_EQ(r.report.status, SolveStatus::kNotConverged);
  EXPECT_NE(r.report.message.find("did not converge"), std::string::npos);
}

}  // namespace
}  // namespace hooke::solve

namespace hooke::solve {
namespace {

// StVK softens in compression and has a limit load; beyond it the only equilibria are inverted (the body
// passed through itself), which the solver must not report.
TEST(StaticEquilibrium, StVKCompressionPastItsLimitLoadIsNotReportedAsConverged) {
  const mesh::Mesh& m = column3d();
  const auto r = static_equilibrium(loaded(m, Law::kStVK, model::LoadKind::kCompress, 0.5 * 14630.0));
  EXPECT_NE(r.report.status, SolveStatus::kConverged) << r.report.message;
  auto model = std::make_shared<model::Model>(3, test::flat_positions(m));
  model->add(fem::make_elastic_block(m, {Law::kStVK, 14630.0, 0.3}));
  EXPECT_TRUE(std::isfinite(model->energy(r.positions))) << "the returned state has an inverted element";
  EXPECT_LT(r.report.load_factor, 1.0);
}

}  // namespace
}  // namespace hooke::solve
