// The quasi-newton integrator (solve/integrators/quasi_newton_step.cpp) against implicit Euler solved by Newton:
// the same incremental potential, so with a tight tolerance both give the same trajectory, for springs with
// volume terms and for FEM; grabbing nodes through the capacitance correction is the same solve as factorising
// with them fixed.
#include <gtest/gtest.h>

#include <cmath>

#include <hooke/calibrate/model_factory.hpp>
#include <hooke/core/error.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/model/mass.hpp>
#include <hooke/solve/simulator.hpp>
#include <iostream>

namespace hooke::solve {
namespace {

struct Column {
  mesh::Mesh mesh;
  std::shared_ptr<const model::Model> model;
  VecX mass;
  std::vector<int> bottom, top;
  explicit Column(const std::string& method) : mesh(mesh::tet_box(0.02, 0.02, 0.04, 2, 2, 4)) {
    if (method == "fem-stvk") {
      auto m = std::make_shared<model::Model>(3, Eigen::Map<const VecX>(mesh.nodes.data(), mesh.nodes.size()));
      m->add(fem::make_elastic_block(mesh, {material::Law::kStVK, 14630.0, 0.45}));
      model = m;
    } else {
      calibrate::ModelOptions o;
      o.method = method;
      o.density = 1000.0;
      model =
          calibrate::build_model(calibrate::calibrate_model(mesh, {material::Law::kLinear, 14630.0, 0.45}, o)).model;
    }
    mass = model::lumped_masses(mesh, 1000.0);
    for (int i = 0; i < mesh.node_count(); ++i) {
      if (mesh.nodes(i, 2) == 0.0) bottom.push_back(i);
      if (mesh.nodes(i, 2) == 0.04) top.push_back(i);
    }
  }
  model::Problem clamped() const {
    model::Problem p = model::make_problem(model);
    model::fix_nodes(p, bottom);
    return p;
  }
};

// Positions after `steps` steps of gravity sideways with the top dragged along y from step 5 on.
VecX run(const Column& c, SimulatorOptions o, int steps, double damping = 0.0) {
  Simulator sim(c.clamped(), {c.mass, Vec3(9.81, 0.0, -9.81), damping, damping * 1e-4}, o);
  for (int k = 0; k < steps; ++k) {
    if (k >= 5) sim.set_probe({c.top, true, Vec3(0.0, 2e-4 * std::min(1.0, (k - 4) / 10.0), 0.0), VecX()});
    sim.step(1e-3);
  }
  return sim.positions();
}

double relative(const VecX& x, const VecX& ref, const VecX& rest) {
  return (x - ref).cwiseAbs().maxCoeff() / (ref - rest).cwiseAbs().maxCoeff();
}

class QuasiNewtonAgainstNewton : public testing::TestWithParam<std::tuple<std::string, QuasiNewtonHessian>> {};

TEST_P(QuasiNewtonAgainstNewton, ConvergedStepsGiveImplicitEulersTrajectory) {
  const Column c(std::get<0>(GetParam()));
  SimulatorOptions newton;
  newton.integrator = Integrator::kImplicitEuler;
  newton.newton.tolerance = 1e-12;
  newton.newton.max_iterations = 100;
  const VecX ref = run(c, newton, 40, 2.0);
  SimulatorOptions qn;
  qn.integrator = Integrator::kQuasiNewton;
  qn.quasi_newton.initial_hessian = std::get<1>(GetParam());
  qn.quasi_newton.isotropic_scale = 2.0;
  qn.quasi_newton.tolerance = 1e-10;
  qn.quasi_newton.max_iterations = 200;
  const double tight = relative(run(c, qn, 40, 2.0), ref, c.model->rest_positions());
  qn.quasi_newton.tolerance = 1e-1;
  qn.quasi_newton.max_iterations = 1;
  const double loose = relative(run(c, qn, 40, 2.0), ref, c.model->rest_positions());
  std::cout << "[quasi-newton] " << std::get<0>(GetParam()) << ": converged " << tight << ", one iteration " << loose
            << " of the largest displacement\n";
  EXPECT_LT(tight, 1e-7);
  EXPECT_GT(loose, 10.0 * tight);  // the comparison can tell an unconverged step
}

INSTANTIATE_TEST_SUITE_P(Models, QuasiNewtonAgainstNewton,
                         testing::Combine(testing::Values("any-nu-tet", "stiffness-fit-volume", "lloyd-tet",
                                                          "fem-stvk"),
                                          testing::Values(QuasiNewtonHessian::kRest, QuasiNewtonHessian::kIsotropic)),
                         [](const auto& p) {
                           std::string name = std::get<0>(p.param) +
                                              (std::get<1>(p.param) == QuasiNewtonHessian::kRest ? "_rest" : "_iso");
                           for (char& ch : name)
                             if (ch == '-') ch = '_';
                           return name;
                         });

// One iteration without history is one solve with H0 restricted to the free DOFs: grabbing the top after the
// factorisation (capacitance correction) and clamping it from the start (factorised that way) take the same step.
TEST(QuasiNewton, GrabbingNodesEqualsFactorisingWithThemFixed) {
  for (QuasiNewtonHessian h : {QuasiNewtonHessian::kRest, QuasiNewtonHessian::kIsotropic}) {
    const Column c("any-nu-tet");
    SimulatorOptions o;
    o.integrator = Integrator::kQuasiNewton;
    o.quasi_newton.initial_hessian = h;
    o.quasi_newton.max_iterations = 1;
    o.quasi_newton.history = 0;
    const Dynamics dyn{c.mass, Vec3(9.81, 0.0, -9.81), 0.0, 0.0};
    Simulator grabbed(c.clamped(), dyn, o);
    grabbed.step(1e-3);  // factorised with the bottom fixed only
    const VecX x1 = grabbed.positions(), v1 = grabbed.velocities();
    grabbed.set_probe({c.top, true, Vec3(1e-4, 0.0, 0.0), VecX()});
    const StepReport r = grabbed.step(1e-3);

    model::Problem both = c.clamped();
    model::fix_nodes(both, c.top);
    VecX target = c.model->rest_positions();
    for (int node : c.top) target.segment<3>(3 * node) = x1.segment<3>(3 * node) + Vec3(1e-4, 0.0, 0.0);
    both.prescribed_positions = target;
    Simulator fixed(both, dyn, o);  // factorised with the top fixed too
    fixed.set_state(x1, v1);
    fixed.step(1e-3);
    const double scale = (grabbed.positions() - c.model->rest_positions()).cwiseAbs().maxCoeff();
    EXPECT_LT((grabbed.positions() - fixed.positions()).cwiseAbs().maxCoeff(), 1e-10 * scale);
    EXPECT_EQ(r.iterations, 1);
    for (int node : c.top)
      EXPECT_EQ((grabbed.positions().segment<3>(3 * node) - target.segment<3>(3 * node)).norm(), 0.0);
  }
}

// A deformation step of a multirate haptic loop is long (a second on 100 k nodes), and the probe moves far in it:
// here a patch of the top (radius 3.5 mm) is dragged sideways by more than its neighbouring tets are wide in one
// step. Moving only the held nodes inverts their neighbours, and so does one solve with H0 from there; the step must
// stay admissible and, held there, settle where a gradual drag (a tenth per step) settles.
TEST(QuasiNewton, AProbeJumpWiderThanAnElementCarriesIntoTheBody) {
  const mesh::Mesh m = mesh::tet_cylinder(0.01, 0.02, 12, 8);
  calibrate::ModelOptions mo;
  mo.method = "any-nu-tet";
  mo.density = 1000.0;
  const auto model =
      calibrate::build_model(calibrate::calibrate_model(m, {material::Law::kLinear, 14630.0, 0.45}, mo)).model;
  std::vector<int> bottom, patch;
  for (int i = 0; i < m.node_count(); ++i) {
    if (m.nodes(i, 2) == 0.0) bottom.push_back(i);
    if (m.nodes(i, 2) > 0.02 - 1e-12 && std::hypot(m.nodes(i, 0), m.nodes(i, 1)) <= 0.0035) patch.push_back(i);
  }
  const double jump = 4e-3;
  for (QuasiNewtonHessian h : {QuasiNewtonHessian::kRest, QuasiNewtonHessian::kIsotropic}) {
    SimulatorOptions o;
    o.integrator = Integrator::kQuasiNewton;
    o.quasi_newton.initial_hessian = h;
    o.quasi_newton.max_iterations = 40;
    const Dynamics dyn{model::lumped_masses(m, 1000.0), Vec3(0.0, 0.0, -9.81), 20.0, 0.0};
    const auto dragged = [&](int ramp_steps) {
      model::Problem p = model::make_problem(model);
      model::fix_nodes(p, bottom);
      Simulator sim(std::move(p), dyn, o);
      sim.step(1.0);  // factorised, settled under gravity
      for (int k = 1; k <= 30; ++k) {
        const double x = jump * std::min(1.0, static_cast<double>(k) / ramp_steps);
        sim.set_probe({patch, true, Vec3(x, 0.0, 0.0), VecX()});
        sim.step(1.0);
        EXPECT_TRUE(std::isfinite(sim.potential_energy())) << "step " << k << " of a " << ramp_steps << "-step drag";
      }
      return sim.positions();
    };
    const VecX once = dragged(1), gradual = dragged(10);
    const double scale = (gradual - model->rest_positions()).cwiseAbs().maxCoeff();
    EXPECT_LT((once - gradual).cwiseAbs().maxCoeff(), 1e-4 * scale);
  }
}

TEST(QuasiNewton, ProbeForceIsTheHoldingForceOfTheStep) {
  const Column c("any-nu-tet");
  SimulatorOptions o;
  o.integrator = Integrator::kQuasiNewton;
  Simulator sim(c.clamped(), {c.mass, Vec3(0.0, 0.0, -9.81), 0.0, 0.0}, o);
  sim.set_probe({c.top, true, Vec3(2e-4, 0.0, 0.0), VecX()});
  const StepReport r = sim.step(1e-3);
  const VecX g = c.model->gradient(sim.positions());
  Vec3 expected = Vec3::Zero();
  for (int node : c.top)
    expected -= g.segment<3>(3 * node) - c.mass.segment<3>(3 * node).cwiseProduct(Vec3(0, 0, -9.81));
  EXPECT_LT((r.probe_force - expected).norm(), 1e-12 * expected.norm());
  EXPECT_GT(expected.norm(), 0.0);
}

// A body at rest with no load is an equilibrium: its step converges at once (the round-off test) and stays where it
// is. Here the body is at rest turned by a rigid rotation, so the model's gradient is round-off, not exactly zero (at
// its rest positions it is zero, and the relative test is met). The step used to run its 8 iterations and report no
// convergence, so `hooke simulate` without a load failed at step 1.
TEST(QuasiNewton, ABodyAtRestWithNoLoadConvergesAtOnce) {
  const mesh::Mesh m = mesh::tet_box(0.023, 0.017, 0.041, 3, 2, 5);
  calibrate::ModelOptions mo;
  mo.method = "any-nu-tet";
  const auto model =
      calibrate::build_model(calibrate::calibrate_model(m, {material::Law::kLinear, 14630.0, 0.45}, mo)).model;
  SimulatorOptions o;
  o.integrator = Integrator::kQuasiNewton;
  Simulator sim(model::make_problem(model), {model::lumped_masses(m, 1000.0), Vec3::Zero(), 0.0, 0.0}, o);
  const Mat3 turn = Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  VecX x = model->rest_positions();
  for (Eigen::Index i = 0; i < x.size() / 3; ++i) x.segment<3>(3 * i) = turn * x.segment<3>(3 * i);
  sim.set_state(x, VecX::Zero(x.size()));
  EXPECT_GT(model->gradient(x).norm(), 0.0);
  for (int k = 0; k < 3; ++k) {
    const StepReport r = sim.step(1e-3);
    EXPECT_TRUE(r.converged) << k;
    EXPECT_EQ(r.iterations, 0) << k;
  }
  EXPECT_LT((sim.positions() - x).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(QuasiNewton, RejectsBadOptions) {
  const Column c("lloyd-tet");
  for (int bad = 0; bad < 3; ++bad) {
    SimulatorOptions o;
    o.integrator = Integrator::kQuasiNewton;
    if (bad == 0) o.quasi_newton.max_iterations = 0;
    if (bad == 1) o.quasi_newton.tolerance = 1.0;
    if (bad == 2) o.quasi_newton.history = -1;
    EXPECT_THROW(Simulator(c.clamped(), {c.mass, VecX(), 0.0, 0.0}, o), InvalidArgument) << bad;
  }
  EXPECT_EQ(integrator_from_name("quasi-newton"), Integrator::kQuasiNewton);
}

}  // namespace
}  // namespace hooke::solve
