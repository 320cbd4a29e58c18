// The benchmark's own cylinders are states a user can reach: no slivers, and 300 steps under gravity with every
// integrator stay admissible (no inverted element, finite, converged where the integrator iterates). The old
// square-to-disc cylinder (minimum tet quality 0.03) inverted an element after 21-31 local/global steps.
#include <gtest/gtest.h>

#include <hooke/core/error.hpp>
#include <hooke/core/quantile.hpp>
#include <hooke/experiments/dynamics_benchmark.hpp>
#include <hooke/mesh/validate.hpp>
#include <hooke/solve/simulation.hpp>
#include <iostream>
#include <string>

namespace hooke::experiments {
namespace {

TEST(BenchmarkCylinder, HasTheDocumentedSizesAndNoSlivers) {
  const int nodes[2] = {1089, 11425};
  for (int size : {0, 1}) {
    const mesh::Mesh m = benchmark_cylinder(size);
    EXPECT_EQ(m.node_count(), nodes[size]);
    double worst = 1.0;
    for (int e = 0; e < m.element_count(); ++e) worst = std::min(worst, mesh::element_quality(m, e));
    EXPECT_GT(worst, 0.25) << m.node_count() << " nodes";
  }
  EXPECT_THROW(benchmark_cylinder(3), InvalidArgument);
}

struct Case {
  solve::Integrator integrator;
  solve::GlobalSolve global_solve;
  int steps;
  solve::NewtonLinearSolver linear_solver = solve::NewtonLinearSolver::kCholesky;
};

class BenchmarkCylinderUnderGravity : public testing::TestWithParam<Case> {};

// 300 steps (the converged Newton integrators, at 0.1-0.3 s a step on 11 425 nodes, run 20, each checked; the
// linearised one with CG, 0.14 s a step against 1.4 s with a factorisation per step).
TEST_P(BenchmarkCylinderUnderGravity, StaysAdmissible) {
  static const calibrate::CalibratedModel model = benchmark_model(1);
  solve::SimulationOptions o;
  o.simulator.integrator = GetParam().integrator;
  o.simulator.global_solve = GetParam().global_solve;
  o.simulator.newton.linear_solver = GetParam().linear_solver;
  o.steps = GetParam().steps;
  o.every = 1;  // solve::simulate() checks every frame: finite, no inverted element
  o.dynamics.gravity = true;
  const bool explicit_step = GetParam().integrator == solve::Integrator::kSymplecticEuler ||
                             GetParam().integrator == solve::Integrator::kVelocityVerlet;
  o.dynamics.dt = explicit_step ? 5e-5 : 1e-3;  // the explicit limit is 6.5e-5 s here
  double sag = 0.0;
  const solve::SimulationSummary s = solve::simulate(model, o, [&](int, double, const VecX& u, const VecX&) {
    for (Eigen::Index i = 2; i < u.size(); i += 3) sag = std::max(sag, -u(i));
  });
  std::cout << "[bench cylinder] " << solve::integrator_name(GetParam().integrator) << ": " << o.steps
            << " steps, largest sag " << sag << " m, median " << quantile(s.step_ms, 0.5) << " ms/step\n";
  EXPECT_EQ(s.not_converged, 0);
  EXPECT_EQ(s.beyond_stable_dt, 0);
  EXPECT_GT(sag, 1e-6);
  EXPECT_LT(sag, 0.02);  // it sags, it does not collapse (height 2 cm)
}

INSTANTIATE_TEST_SUITE_P(Integrators, BenchmarkCylinderUnderGravity,
                         testing::Values(Case{solve::Integrator::kSymplecticEuler, solve::GlobalSolve::kDirect, 300},
                                         Case{solve::Integrator::kVelocityVerlet, solve::GlobalSolve::kDirect, 300},
                                         Case{solve::Integrator::kLocalGlobal, solve::GlobalSolve::kDirect, 300},
                                         Case{solve::Integrator::kLocalGlobal, solve::GlobalSolve::kChebyshev, 300},
                                         Case{solve::Integrator::kImplicitEulerLinearised, solve::GlobalSolve::kDirect,
                                              300, solve::NewtonLinearSolver::kConjugateGradient},
                                         Case{solve::Integrator::kQuasiNewton, solve::GlobalSolve::kDirect, 300},
                                         Case{solve::Integrator::kImplicitEuler, solve::GlobalSolve::kDirect, 20},
                                         Case{solve::Integrator::kQuasiStatic, solve::GlobalSolve::kDirect, 20}),
                         [](const testing::TestParamInfo<Case>& p) {
                           std::string name(solve::integrator_name(p.param.integrator));
                           if (p.param.global_solve == solve::GlobalSolve::kChebyshev) name += "_chebyshev";
                           if (p.param.linear_solver == solve::NewtonLinearSolver::kConjugateGradient) name += "_cg";
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

}  // namespace
}  // namespace hooke::experiments

namespace hooke::experiments {
namespace {

// The benchmark's tool press: a 5 mm sphere pressed 10 % into the 1 089-node cylinder, the quasi-Newton row against
// the converged implicit Euler reference, by positions and by the force on the sphere.
TEST(DynamicsBenchmark, ASpherePressedIntoTheCylinderMatchesTheConvergedReference) {
  DynamicsBenchmarkOptions o;
  o.sizes = {0};
  o.methods = {"any-nu-tet"};
  o.tool_radius = 0.005;
  o.tool_press = 0.1;
  o.steps = 40;
  o.integrators = {"quasi-newton (rest)"};
  const DynamicsBenchmarkReport r = run_dynamics_benchmark(o);
  ASSERT_EQ(r.steps.size(), 1u) << (r.notes.empty() ? "" : r.notes[0]);
  const StepTiming& t = r.steps[0];
  EXPECT_GT(t.reference_tool_force, 0.05);
  EXPECT_LT(std::abs(t.tool_force - t.reference_tool_force), 0.01 * t.reference_tool_force);
  EXPECT_LT(t.error_vs_converged, 1e-2);
  EXPECT_NE(dynamics_benchmark_markdown(r).find("The force on the pressing sphere"), std::string::npos);
}

}  // namespace
}  // namespace hooke::experiments
