// The viewer's physics without a window: a quasi-static drag's reaction force against an independently assembled
// static equilibrium, settings changed live (the springs then equal a fresh calibration; the deformation is kept),
// failed recalibrations that change nothing, script settings.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/calibrate/model_settings.hpp>
#include <hooke/core/error.hpp>
#include <hooke/interactive/live_simulation.hpp>
#include <hooke/interactive/physics_loop.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/model/problem.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <hooke/solve/tool_press.hpp>
#include <iostream>
#include <map>
#include <thread>
#include "interactive/support.hpp"

namespace hooke::interactive {
namespace {

// The holding force of the equilibrium with `node` held at rest + offset, the bottom clamped: a problem assembled
// here by hand, solved by solve::static_equilibrium, and the reaction -(dE/dx - f) at the node.
Vec3 reference_force(const calibrate::CalibratedModel& cm, const std::vector<int>& clamped, int node,
                     const Vec3& offset, VecX* positions = nullptr) {
  const calibrate::BuiltModel built = calibrate::build_model(cm);
  model::Problem p = model::make_problem(built.model);
  model::fix_nodes(p, clamped);
  model::fix_nodes(p, {node});
  p.prescribed_positions = built.model->rest_positions();
  p.prescribed_positions.segment<3>(3 * node) += offset;
  solve::StaticOptions o;
  o.start = solve::linear_static(p).positions;
  const solve::StaticResult r = solve::static_equilibrium(p, o);
  EXPECT_EQ(r.report.status, solve::SolveStatus::kConverged) << r.report.message;
  if (positions) *positions = r.positions;
  return -built.model->gradient(r.positions).segment<3>(3 * node);
}

TEST(LiveSimulation, QuasiStaticDragFeelsTheStaticHoldingForce) {
  const mesh::Mesh m = cylinder();
  const int node = top_node(m);
  const Vec3 offset(1e-3, 0.0, -0.5e-3);
  for (const solve::Integrator integrator :
       {solve::Integrator::kImplicitEuler, solve::Integrator::kQuasiStatic, solve::Integrator::kQuasiNewton}) {
    LiveSettings s = settings();
    s.simulator.integrator = integrator;
    LiveSimulation sim(m, s);
    sim.grab({node});
    // Ramped over 0.3 s, then 1.2 s to settle under mass damping (the viewer's scripted quasi-static drag).
    for (int k = 1; k <= 1500; ++k) {
      sim.drag(std::min(1.0, k / 300.0) * offset);
      sim.step();
    }
    const Vec3 expected = reference_force(sim.model(), sim.clamped_nodes(), node, offset);
    const Vec3 felt = sim.probe_force();
    EXPECT_LT((felt - expected).norm(), 0.01 * expected.norm())
        << solve::integrator_name(integrator) << ": felt " << felt.transpose() << " N, static " << expected.transpose();
    // The library's own probe equilibrium (the viewer's FEM ghost path) agrees with the hand-made one.
    const ProbeEquilibrium pe = probe_equilibrium(sim.model(), sim.clamped_nodes(), {node},
                                                  VecX(m.nodes.row(node).transpose() + offset), false);
    EXPECT_LT((pe.holding_force - expected).norm(), 1e-8 * expected.norm());
  }
}

TEST(LiveSimulation, FemGhostIsTheFemModelsEquilibrium) {
  const mesh::Mesh m = cylinder();
  const int node = top_node(m);
  const Vec3 offset(0.0, 1e-3, 0.0);
  LiveSimulation sim(m, settings("fem"));
  const ProbeEquilibrium ghost = fem_probe_equilibrium(sim.model(), material::Law::kLinear, sim.clamped_nodes(), {node},
                                                       VecX(m.nodes.row(node).transpose() + offset), false);
  VecX x;
  const Vec3 expected = reference_force(sim.model(), sim.clamped_nodes(), node, offset, &x);
  EXPECT_LT((ghost.holding_force - expected).norm(), 1e-8 * expected.norm());
  EXPECT_LT((ghost.positions - x).norm(), 1e-10);
  // A surface mesh has no FEM reference.
  const mesh::Mesh surface = mesh::uv_sphere_surface(6, 8, 0.01);
  calibrate::ModelOptions so;
  so.method = "surface";
  const calibrate::CalibratedModel sm = calibrate::calibrate_model(surface, {material::Law::kLinear, 1e4, 0.3}, so);
  EXPECT_THROW(
      fem_probe_equilibrium(sm, material::Law::kLinear, {}, {0}, VecX(surface.nodes.row(0).transpose()), false),
      InvalidArgument);
}

TEST(LiveSimulation, ChangingNuRecalibratesExactlyAndKeepsTheDeformation) {
  const mesh::Mesh m = cylinder();
  LiveSimulation sim(m, settings("stiffness-fit", 0.3));
  sim.grab({top_node(m)});
  sim.drag(Vec3(1e-3, 0.0, 0.0));
  for (int k = 0; k < 50; ++k) sim.step();
  const VecX x = sim.positions(), v = sim.velocities();
  LiveSettings s = sim.settings();
  s.material.poisson_ratio = 0.45;
  sim.apply(s);
  EXPECT_EQ(sim.positions(), x);
  EXPECT_EQ(sim.velocities(), v);
  calibrate::ModelOptions o;
  o.method = "stiffness-fit";
  const calibrate::CalibratedModel fresh = calibrate::calibrate_model(m, s.material, o);
  EXPECT_EQ(sim.model().springs.pairs, fresh.springs.pairs);
  EXPECT_EQ(sim.model().springs.stiffness, fresh.springs.stiffness);  // exactly what hooke calibrate writes
  EXPECT_EQ(sim.model().springs.rest_length, fresh.springs.rest_length);
  // The probe still holds its node where it was dragged, and the run goes on.
  EXPECT_EQ(sim.grabbed().size(), 1u);
  for (int k = 0; k < 20; ++k) sim.step();
  EXPECT_LT((sim.positions().segment<3>(3 * top_node(m)) - x.segment<3>(3 * top_node(m))).norm(), 1e-9);
}

TEST(LiveSimulation, AFailedRecalibrationChangesNothing) {
  const mesh::Mesh m = cylinder();
  LiveSimulation sim(m, settings());
  for (int k = 0; k < 5; ++k) sim.step();
  const VecX x = sim.positions();
  LiveSettings s = sim.settings();
  s.model.method = "surface";  // needs a closed surface-triangle mesh
  EXPECT_THROW(sim.apply(s), Error);
  s = sim.settings();
  s.dynamics.dt = -1.0;
  EXPECT_THROW(sim.apply(s), InvalidArgument);
  s = sim.settings();
  s.material.poisson_ratio = 0.5;
  EXPECT_THROW(sim.apply(s), Error);
  EXPECT_EQ(sim.settings().model.method, "lloyd-tet");
  EXPECT_EQ(sim.positions(), x);
  EXPECT_THROW(sim.grab({m.node_count()}), InvalidArgument);
  EXPECT_THROW(sim.grab({}), InvalidArgument);
}

TEST(LiveSimulation, SurfaceModelWeightsFollowTheProbe) {
  const mesh::Mesh surface = mesh::uv_sphere_surface(8, 12, 0.02);
  LiveSimulation sim(surface, settings("surface"));
  EXPECT_TRUE(sim.clamped_nodes().empty());
  ASSERT_NE(sim.volume_penalty(), nullptr);
  sim.grab({0});
  EXPECT_FALSE(sim.interaction().has_value());  // no direction before a drag
  sim.drag(Vec3(0.0, 0.0, -2e-3));
  ASSERT_TRUE(sim.interaction().has_value());
  EXPECT_EQ(sim.interaction()->point, Vec3(surface.nodes.row(0).transpose()));
  for (int k = 0; k < 20; ++k) sim.step();
  EXPECT_GT(sim.probe_force().norm(), 0.0);
  sim.release();
  EXPECT_FALSE(sim.interaction().has_value());
}

TEST(ApplySetting, ParsesAndRefuses) {
  LiveSettings s;
  apply_setting(s, "young", "2e4");
  apply_setting(s, "gravity", "on");
  apply_setting(s, "integrator", "local-global");
  EXPECT_EQ(s.material.youngs_modulus, 2e4);
  EXPECT_TRUE(s.dynamics.gravity);
  EXPECT_EQ(s.simulator.integrator, solve::Integrator::kLocalGlobal);
  EXPECT_THROW(apply_setting(s, "young", "nan"), InvalidArgument);
  EXPECT_THROW(apply_setting(s, "young", "1e4x"), InvalidArgument);
  EXPECT_THROW(apply_setting(s, "gravity", "maybe"), InvalidArgument);
  EXPECT_THROW(apply_setting(s, "integrator", "rk4"), InvalidArgument);
}

// The viewer's scripts take every declared live model setting (its panel draws one control per row): each is set
// at a value other than its default, lands in the settings, and a live simulation recalibrates with it.
TEST(ApplySetting, EveryLiveModelSettingIsASetKey) {
  const std::map<std::string, std::string> values = {
      {"method", "any-nu-tet"}, {"density", "1100"},      {"spring-exponent", "0.5"}, {"volume-exponent", "-1"},
      {"scheme", "B"},          {"anchor-law", "tensor"}, {"volume-force", "energy"}};
  const auto rows = calibrate::model_settings();
  ASSERT_FALSE(live_model_settings().empty());
  LiveSettings s = settings("lloyd-tet", 0.3);
  LiveSimulation sim(calibrate::calibrate_model(cylinder(), s.material, s.model), s);
  for (const hooke::settings::Description& d : live_model_settings()) {
    ASSERT_TRUE(values.count(d.name)) << d.name << " has no test value here";
    const auto row = std::find_if(rows.begin(), rows.end(), [&](const auto& r) { return r.name == d.name; });
    apply_setting(s, d.name, values.at(d.name));
    EXPECT_EQ(row->get(s.model), values.at(d.name)) << d.name;
  }
  sim.apply(s);
  EXPECT_EQ(sim.model().method, "any-nu-tet");
  EXPECT_EQ(sim.model().springs.spring_exponent, 0.5);
  EXPECT_EQ(sim.model().springs.volume_exponent, -1.0);
  EXPECT_EQ(sim.model().density, 1100.0);
  EXPECT_THROW(apply_setting(s, "density", "0"), InvalidArgument);  // the declared range, as on the command line
  EXPECT_THROW(apply_setting(s, "spring-exponent", "9"), InvalidArgument);
  EXPECT_THROW(apply_setting(s, "method", "lloyd"), InvalidArgument);
}

// A model file with a method hooke calibrates is remade by it when the material changes (the viewer's sliders on
// `--model`); one with constants of its own ("file") refuses a new material instead of showing it and running the
// old springs (which it did before: the settings took nu = 0.45, the springs stayed those of 0.3).
TEST(LiveSimulation, AModelFileIsRecalibratedByItsMethodOrRefusesANewMaterial) {
  const mesh::Mesh m = cylinder();
  calibrate::ModelOptions o;
  o.method = "lloyd-tet";
  const material::Material at3{material::Law::kLinear, 14630.0, 0.3};
  calibrate::CalibratedModel made = calibrate::calibrate_model(m, at3, o);
  EXPECT_EQ(live_method_for(made), "lloyd-tet");
  EXPECT_EQ(live_method_for(calibrate::calibrate_model(m, at3, {})), "auto");
  LiveSettings s = settings(live_method_for(made), 0.3);
  LiveSimulation sim(made, s);
  EXPECT_EQ(sim.model().springs.stiffness, made.springs.stiffness);  // run as it is
  s.material.poisson_ratio = 0.45;
  sim.apply(s);
  o.method = "lloyd-tet";
  const calibrate::CalibratedModel fresh = calibrate::calibrate_model(m, {material::Law::kLinear, 14630.0, 0.45}, o);
  EXPECT_EQ(sim.model().material.poisson_ratio, 0.45);
  EXPECT_EQ(sim.model().springs.stiffness, fresh.springs.stiffness);

  calibrate::CalibratedModel tuned = made;
  tuned.method = "hand-tuned";
  tuned.springs.stiffness *= 1.5;
  EXPECT_EQ(live_method_for(tuned), "file");
  LiveSettings f = settings("file", 0.3);
  LiveSimulation own(tuned, f);
  EXPECT_EQ(own.model().springs.stiffness, tuned.springs.stiffness);
  f.material.poisson_ratio = 0.45;
  EXPECT_THROW(own.apply(f), InvalidArgument);
  EXPECT_EQ(own.settings().material.poisson_ratio, 0.3);
  EXPECT_EQ(own.model().springs.stiffness, tuned.springs.stiffness);
  f.material.poisson_ratio = 0.3;
  f.dynamics.damping_mass = 10.0;  // other settings still apply
  own.apply(f);
  EXPECT_EQ(own.settings().dynamics.damping_mass, 10.0);
}

}  // namespace
}  // namespace hooke::interactive

namespace hooke::interactive {
namespace {

// A sphere pressed 3 mm into the top of the live body (implicit Euler, ramped over 0.2 s, held to rest): no node ever
// inside it, and at rest the force on it equals the quasi-static press's at the same pose (solve::press_quasi_
// statically on a problem assembled here). A new nu keeps the tool and the clock; removing it leaves no force.
TEST(LiveSimulation, ASpherePressedIntoTheTopSettlesOnTheStaticPressAndSurvivesARecalibration) {
  const mesh::Mesh m = cylinder();
  const double top = m.nodes.col(2).maxCoeff(), r = 0.005;
  LiveSettings s = settings("any-nu-tet", 0.45);
  s.simulator.integrator = solve::Integrator::kImplicitEuler;
  LiveSimulation sim(m, s);
  EXPECT_THROW(sim.set_tool("cube:1", {}), InvalidArgument);
  sim.set_tool("sphere:0.005", {Vec3(0.0, 0.0, top + r + 1e-3), Mat3::Identity()});
  ASSERT_TRUE(sim.tool());
  double smallest = 1.0;
  for (int k = 1; k <= 1000; ++k) {
    sim.move_tool({Vec3(0.0, 0.0, top + r + 1e-3 - 4e-3 * std::min(1.0, k / 200.0)), Mat3::Identity()});
    sim.step();
    smallest = std::min(smallest, sim.tool()->smallest_gap);
  }
  EXPECT_GT(smallest, 0.0);
  const Vec3 live = sim.tool()->force;

  auto tool = std::make_shared<contact::RigidTool>(contact::ToolShape::kSphere, r);
  const calibrate::BuiltModel built = calibrate::build_model(sim.model());
  auto block = contact::boundary_contact(sim.model().mesh, sim.model().material.youngs_modulus, tool);
  const contact::ContactBlock& contact = *block;
  built.model->add(std::move(block));
  model::Problem p = model::make_problem(built.model);
  model::fix_nodes(p, sim.clamped_nodes());
  std::vector<contact::Pose> poses;
  for (int k = 0; k <= 6; ++k) poses.push_back({Vec3(0.0, 0.0, top + r - 0.5e-3 * k), Mat3::Identity()});
  tool->set_pose(poses[0]);
  const Vec3 still = solve::press_quasi_statically(p, contact, *tool, poses).back().tool_force;
  std::cout << "[live press] " << live.transpose() << " N live, " << still.transpose() << " N static\n";
  EXPECT_GT(still.z(), 0.01);
  EXPECT_LT((live - still).norm(), 0.01 * still.norm());

  const double t = sim.time();
  LiveSettings stiffer = sim.settings();
  stiffer.material.poisson_ratio = 0.3;
  sim.apply(stiffer);
  EXPECT_EQ(sim.time(), t);
  ASSERT_TRUE(sim.tool());
  for (int k = 0; k < 20; ++k) sim.step();
  EXPECT_GT(sim.tool()->smallest_gap, 0.0);
  EXPECT_GT(sim.tool()->force.z(), 0.0);
  sim.remove_tool();
  EXPECT_FALSE(sim.tool());
  sim.step();
}

}  // namespace
}  // namespace hooke::interactive
