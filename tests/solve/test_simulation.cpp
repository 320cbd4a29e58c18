// Scripted runs: a model read back from its file runs the same trajectory as the calibrated one, one model is
// stepped by two simulators on two threads at once, and bad options are refused by the library.
#include <gtest/gtest.h>

#include <map>

#include <hooke/calibrate/surface_model.hpp>
#include <hooke/mesh/generators.hpp>

#include <cmath>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/calibrate/model_file.hpp>
#include <hooke/contact/contact_block.hpp>
#include <hooke/core/error.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/model/load_case.hpp>
#include <hooke/solve/simulation.hpp>
#include <hooke/solve/tool_press.hpp>
#include <iostream>
#include <thread>

namespace hooke::solve {
namespace {

calibrate::CalibratedModel cylinder(const std::string& method = "lloyd-tet") {
  calibrate::ModelOptions o;
  o.method = method;
  return calibrate::calibrate_model(mesh::tet_cylinder(0.01, 0.04, 8, 6), {material::Law::kLinear, 14630.0, 0.3}, o);
}

std::vector<VecX> run(const calibrate::CalibratedModel& m, const SimulationOptions& o) {
  std::vector<VecX> frames;
  simulate(m, o, [&](int, double, const VecX& u, const VecX&) { frames.push_back(u); });
  return frames;
}

SimulationOptions gravity_run(solve::Integrator integrator) {
  SimulationOptions o;
  o.simulator.integrator = integrator;
  o.steps = 30;
  o.every = 10;
  o.dynamics.gravity = true;
  o.dynamics.damping_mass = 2.0;
  o.probe_node = 5;
  o.probe_offset = Vec3(0.0, 1e-3, 0.0);
  return o;
}

class ModelFromFile : public testing::TestWithParam<solve::Integrator> {};

TEST_P(ModelFromFile, RunsTheTrajectoryOfTheCalibratedModel) {
  const calibrate::CalibratedModel a = cylinder();
  const calibrate::CalibratedModel b = calibrate::parse_model(calibrate::model_json(a), "m.json");
  SimulationOptions o = gravity_run(GetParam());
  if (GetParam() == solve::Integrator::kSymplecticEuler) o.dynamics.dt = 1e-5;
  const auto fa = run(a, o), fb = run(b, o);
  ASSERT_EQ(fa.size(), 4u);
  ASSERT_EQ(fb.size(), fa.size());
  EXPECT_GT(fa.back().norm(), 1e-6);  // it moved
  for (size_t k = 0; k < fa.size(); ++k) EXPECT_LE((fa[k] - fb[k]).cwiseAbs().maxCoeff(), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Integrators, ModelFromFile,
                         testing::Values(solve::Integrator::kSymplecticEuler, solve::Integrator::kImplicitEuler,
                                         solve::Integrator::kLocalGlobal, solve::Integrator::kQuasiStatic));

TEST(Simulation, ReorderingKeepsTheTrajectoryInTheModelsNumbering) {
  const calibrate::CalibratedModel m = cylinder();
  SimulationOptions o = gravity_run(solve::Integrator::kLocalGlobal);
  const auto reordered = run(m, o);
  o.reorder = false;
  const auto plain = run(m, o);
  EXPECT_LT((reordered.back() - plain.back()).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(Simulation, OneModelSteppedByTwoSimulatorsOnTwoThreads) {
  const auto built = calibrate::build_model(cylinder());
  const calibrate::CalibratedModel cm = cylinder();
  model::Problem problem = model::make_problem(built.model);
  model::fix_nodes(problem, {0, 1, 2});
  auto trajectory = [&](double gravity) {
    solve::Dynamics dyn{cm.masses, Vec3(0.0, 0.0, gravity), 1.0, 0.0};
    solve::SimulatorOptions so;
    so.integrator = solve::Integrator::kImplicitEuler;
    solve::Simulator sim(problem, dyn, so);
    for (int k = 0; k < 15; ++k) sim.step(1e-3);
    return sim.positions();
  };
  const VecX serial_a = trajectory(-9.81), serial_b = trajectory(-3.0);
  VecX parallel_a, parallel_b;
  std::thread ta([&] { parallel_a = trajectory(-9.81); });
  std::thread tb([&] { parallel_b = trajectory(-3.0); });
  ta.join();
  tb.join();
  EXPECT_LT((serial_a - built.model->rest_positions()).norm(), 1.0);
  EXPECT_GT((serial_a - serial_b).norm(), 1e-7);  // two different runs
  EXPECT_LE((parallel_a - serial_a).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_LE((parallel_b - serial_b).cwiseAbs().maxCoeff(), 1e-13);
}

// The surface model's volume penalty follows an interaction (Eq. 4); the interaction lives in each problem, so
// one model pushed at two places by two threads gives each thread the trajectory it gives alone.
TEST(Simulation, OneSurfaceModelPushedAtTwoPlacesOnTwoThreads) {
  const calibrate::SurfaceModel s =
      calibrate::make_surface_model(mesh::uv_sphere_surface(12, 20, 0.05), {material::Law::kLinear, 1000.0, 0.3});
  const int top = 0, bottom = s.mesh.node_count() - 1;
  auto trajectory = [&](int node, double sense) {
    model::Problem problem = model::make_problem(s.model);
    problem.interaction = model::Interaction{s.mesh.nodes.row(node).transpose(), Vec3(0, 0, sense), 0.1};
    solve::SimulatorOptions so;
    so.integrator = solve::Integrator::kImplicitEuler;
    solve::Simulator sim(problem, {s.masses, VecX(), 2.0, 0.0}, so);
    sim.set_probe({{node}, false, VecX(), Vec3(0.0, 0.0, 0.02 * sense)});
    for (int k = 0; k < 20; ++k) sim.step(1e-3);
    return sim.positions();
  };
  const VecX serial_a = trajectory(top, -1.0), serial_b = trajectory(bottom, 1.0);
  VecX parallel_a, parallel_b;
  std::thread ta([&] { parallel_a = trajectory(top, -1.0); });
  std::thread tb([&] { parallel_b = trajectory(bottom, 1.0); });
  ta.join();
  tb.join();
  EXPECT_GT((serial_a - s.model->rest_positions()).norm(), 1e-6);
  EXPECT_GT((serial_a - serial_b).norm(), 1e-6);
  EXPECT_LE((parallel_a - serial_a).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_LE((parallel_b - serial_b).cwiseAbs().maxCoeff(), 1e-13);
}

TEST(Simulation, RefusesOptionsOutOfRange) {
  const calibrate::CalibratedModel m = cylinder();
  auto refuses = [&](auto change) {
    SimulationOptions o;
    o.steps = 2;
    change(o);
    EXPECT_THROW(run(m, o), InvalidArgument);
  };
  refuses([](SimulationOptions& o) { o.dynamics.dt = 0.0; });
  refuses([](SimulationOptions& o) { o.dynamics.dt = std::nan(""); });
  refuses([](SimulationOptions& o) { o.steps = 0; });
  refuses([](SimulationOptions& o) { o.dynamics.damping_mass = -1.0; });
  refuses([](SimulationOptions& o) { o.dynamics.damping_stiffness = std::nan(""); });
  refuses([](SimulationOptions& o) {
    o.simulator.integrator = solve::Integrator::kLocalGlobal;
    o.simulator.local_global_iterations = 0;
  });
  refuses([](SimulationOptions& o) { o.probe_node = 3; });  // neither offset nor force
  refuses([](SimulationOptions& o) {
    o.probe_node = 100000;
    o.probe_force = Vec3(0, 0, 1);
  });
}

TEST(Simulator, LibraryRefusesInvalidOptions) {
  const auto built = calibrate::build_model(cylinder());
  const calibrate::CalibratedModel cm = cylinder();
  const model::Problem problem = model::make_problem(built.model);
  solve::SimulatorOptions lg;
  lg.integrator = solve::Integrator::kLocalGlobal;
  lg.local_global_iterations = 0;
  EXPECT_THROW(solve::Simulator(problem, {cm.masses, VecX(), 0.0, 0.0}, lg), InvalidArgument);
  EXPECT_THROW(solve::Simulator(problem, {cm.masses, VecX(), -1.0, 0.0}), InvalidArgument);
  solve::Simulator sim(problem, {cm.masses, VecX(), 0.0, 0.0});
  EXPECT_THROW(sim.step(0.0), InvalidArgument);
  EXPECT_THROW(sim.step(-1e-3), InvalidArgument);
}

}  // namespace
}  // namespace hooke::solve

namespace hooke::solve {
namespace {

// A sphere pressed 3 mm into the top of a tissue cylinder and held, with implicit Euler and with the quasi-Newton
// real-time path: no node enters the sphere at any step, and once the body has come to rest the force on the sphere is
// the quasi-static press's at the same pose (solve::press_quasi_statically on the same model and contact block), to
// 2 % with implicit Euler and 10 % with the quasi-Newton path.
TEST(Simulation, ASpherePressedIntoTheTopSettlesOnTheStaticForce) {
  const calibrate::CalibratedModel m = cylinder("any-nu-tet");
  const double top = m.mesh.nodes.col(2).maxCoeff(), radius = 0.005;
  const auto at = [&](double depth) { return contact::Pose{Vec3(0.0, 0.0, top + radius - depth), Mat3::Identity()}; };
  const contact::ToolPath path({{0.0, at(-0.5e-3)}, {0.2, at(3e-3)}});
  for (const Integrator integrator : {Integrator::kImplicitEuler, Integrator::kQuasiNewton}) {
    SimulationOptions o;
    o.simulator.integrator = integrator;
    o.dynamics.dt = 2e-3;
    o.dynamics.damping_mass = 40.0;
    o.steps = 300;
    o.every = 300;
    o.tool = std::make_shared<contact::RigidTool>(contact::ToolShape::kSphere, radius);
    o.tool_path = path;
    o.allow_unconverged = integrator == Integrator::kQuasiNewton;
    const SimulationSummary s = simulate(m, o, [](int, double, const VecX&, const VecX&) {});
    ASSERT_EQ(s.tool_force.size(), 300u);
    EXPECT_GT(s.smallest_gap, 0.0) << integrator_name(integrator);
    EXPECT_LT(s.smallest_gap, s.contact_distance) << integrator_name(integrator);

    // the static press on the same model, the bottom clamped as simulate clamps it
    auto tool = std::make_shared<contact::RigidTool>(contact::ToolShape::kSphere, radius);
    calibrate::BuiltModel built = calibrate::build_model(m);
    auto block = contact::boundary_contact(m.mesh, m.material.youngs_modulus, tool, s.contact_distance);
    const contact::ContactBlock& contact = *block;
    built.model->add(std::move(block));
    model::Problem problem = model::make_problem(built.model);
    model::fix_nodes(problem, model::make_load_case(m.mesh, model::LoadKind::kStretch, 0.0).fixed_nodes);
    std::vector<contact::Pose> poses;
    for (int k = 1; k <= 7; ++k) poses.push_back(at(0.5e-3 * k - 0.5e-3));
    const auto steps = press_quasi_statically(problem, contact, *tool, poses);
    const double fz = steps.back().tool_force.z(), dz = s.tool_force.back()[3];
    std::cout << "[press] " << integrator_name(integrator) << ": dynamic " << dz << " N, static " << fz << " N\n";
    EXPECT_GT(fz, 0.0);
    // Both settle on the static force (measured equal to six digits). Without the contact's stiffness in its initial
    // Hessian the quasi-Newton steps ended at their iteration budget, 4.4 % high; with it, 21 of 300 steps (during
    // the press) end above the tolerance.
    EXPECT_NEAR(dz, fz, 0.01 * fz) << integrator_name(integrator);
    std::cout << "[press] " << integrator_name(integrator) << ": " << s.not_converged
              << " of 300 steps above tolerance\n";
    EXPECT_LT(s.not_converged, 30) << integrator_name(integrator);
  }
}

// A free cube under gravity dropped 0.5 mm onto a floor comes to rest on it: no node below the floor at any step, and
// at rest the floor carries the cube's weight (sum of the lumped masses times g) to 1 %.
TEST(Simulation, AFreeBodyComesToRestOnAFloorAndTheFloorCarriesItsWeight) {
  calibrate::ModelOptions mo;
  mo.method = "any-nu-tet";
  const calibrate::CalibratedModel cube =
      calibrate::calibrate_model(mesh::tet_box(0.02, 0.02, 0.02, 3, 3, 3), {material::Law::kLinear, 14630.0, 0.45}, mo);
  SimulationOptions o;
  o.simulator.integrator = Integrator::kImplicitEuler;
  o.dynamics.dt = 2e-3;
  o.dynamics.gravity = true;
  o.dynamics.damping_mass = 20.0;
  o.clamp_bottom = false;
  o.steps = 400;
  o.every = 400;
  o.obstacles.push_back(contact::parse_obstacle("plane:0,0,-0.0005"));
  const SimulationSummary s = simulate(cube, o, [](int, double, const VecX&, const VecX&) {});
  ASSERT_EQ(s.obstacle_force.size(), 1u);
  const double weight = cube.masses.sum() / 3.0 * 9.81;
  EXPECT_GT(s.obstacle_gap[0], 0.0);
  std::cout << "[floor] " << -s.obstacle_force[0][2] << " N on the floor, weight " << weight << " N, gap "
            << s.obstacle_gap[0] << " m\n";
  EXPECT_NEAR(-s.obstacle_force[0][2], weight, 0.01 * weight);
  EXPECT_LT(std::hypot(s.obstacle_force[0][0], s.obstacle_force[0][1]), 1e-6 * weight);
  // starting inside an obstacle is refused
  o.obstacles = {contact::parse_obstacle("plane:0,0,0.01")};
  EXPECT_THROW(simulate(cube, o, [](int, double, const VecX&, const VecX&) {}), InvalidArgument);
}

// Coulomb friction on an inclined plane (a free tissue cube on a plane tilted by theta, gravity down, implicit Euler):
// with tan(theta) < mu the cube stays put (its contact nodes creep slower than the creep velocity); beyond it, it
// slides with Newton's acceleration g (sin theta - mu cos theta), and without friction with g sin theta.
struct Slide {
  double acceleration;    // of the mean velocity along the slope between 0.1 s and 0.3 s, m/s^2
  double contact_slip;    // the bottom face's mean displacement along the slope from 0.1 s (landed) to 0.3 s, m
  double creep_velocity;  // eps_v, m/s: the default, 1e-3 of the cube's diagonal per second
};
Slide slide_on_a_slope(double theta_degrees, double mu) {
  const double theta = theta_degrees * std::acos(-1.0) / 180.0;
  const Mat3 tilt = Eigen::AngleAxisd(theta, Vec3::UnitX()).toRotationMatrix();
  mesh::Mesh box = mesh::tet_box(0.02, 0.02, 0.02, 3, 3, 3);
  std::vector<int> bottom;
  for (int i = 0; i < box.node_count(); ++i)
    if (box.nodes(i, 2) < 1e-12) bottom.push_back(i);
  box.nodes = (box.nodes * tilt.transpose()).eval();
  calibrate::ModelOptions mo;
  mo.method = "any-nu-tet";
  const calibrate::CalibratedModel cube = calibrate::calibrate_model(box, {material::Law::kLinear, 14630.0, 0.45}, mo);
  const Vec3 normal = tilt * Vec3::UnitZ(), downhill = tilt * -Vec3::UnitY();  // the plane's normal, down the slope
  contact::RigidTool plane(contact::ToolShape::kHalfSpace);
  plane.set_pose({-1e-4 * normal, contact::rotation_to(normal)});  // 0.1 mm below: the cube drops onto it
  SimulationOptions o;
  o.simulator.integrator = Integrator::kImplicitEuler;
  o.dynamics.dt = 1e-3;
  o.dynamics.gravity = true;
  o.clamp_bottom = false;
  o.steps = 300;
  o.every = 100;
  o.obstacles = {plane};
  o.friction = mu;
  o.dynamics.damping_stiffness = 2e-3;  // damps the landing's vibrations (which make a contact walk), not the sliding
  std::map<int, Vec3> mean_velocity;
  Slide out{0.0, 0.0, 0.0};
  const SimulationSummary sum = simulate(cube, o, [&](int k, double, const VecX& u, const VecX& v) {
    mean_velocity[k] = v.reshaped(3, v.size() / 3).rowwise().mean();
    const double sign = k == 300 ? 1.0 : k == 100 ? -1.0 : 0.0;
    for (int i : bottom)
      out.contact_slip += sign * u.segment<3>(3 * i).dot(downhill) / static_cast<double>(bottom.size());
  });
  out.creep_velocity = sum.creep_velocity;
  out.acceleration = (mean_velocity.at(300) - mean_velocity.at(100)).dot(downhill) / 0.2;
  return out;
}

TEST(Simulation, ABodyOnAnInclinedPlaneStaysBelowTheFrictionAngleAndSlidesAboveIt) {
  const double g = 9.81, deg = std::acos(-1.0) / 180.0;
  const Slide stuck = slide_on_a_slope(20.0, 0.5), sliding = slide_on_a_slope(35.0, 0.5),
              frictionless = slide_on_a_slope(20.0, 0.0);
  std::cout << "[slope] 20 deg, mu 0.5: slip " << stuck.contact_slip << " m, acceleration " << stuck.acceleration
            << "; 35 deg, mu 0.5: " << sliding.acceleration << " m/s^2 (Newton "
            << g * (std::sin(35 * deg) - 0.5 * std::cos(35 * deg)) << "), slip " << sliding.contact_slip
            << " m; 20 deg, mu 0: " << frictionless.acceleration << " (Newton " << g * std::sin(20 * deg) << ")\n";
  EXPECT_LT(std::abs(stuck.contact_slip), stuck.creep_velocity * 0.2);  // slower than eps_v from 0.1 s to 0.3 s
  EXPECT_NEAR(sliding.acceleration, g * (std::sin(35 * deg) - 0.5 * std::cos(35 * deg)),
              0.03 * g * (std::sin(35 * deg) - 0.5 * std::cos(35 * deg)));
  EXPECT_NEAR(frictionless.acceleration, g * std::sin(20 * deg), 0.03 * g * std::sin(20 * deg));
  EXPECT_GT(sliding.contact_slip, 1e3 * std::abs(stuck.contact_slip));
  // either side of the friction angle atan(0.5) = 26.6 deg
  const Slide below = slide_on_a_slope(25.0, 0.5), above = slide_on_a_slope(28.0, 0.5);
  std::cout << "[slope] 25 deg: slip " << below.contact_slip << " m; 28 deg: " << above.acceleration
            << " m/s^2 (Newton " << g * (std::sin(28 * deg) - 0.5 * std::cos(28 * deg)) << ")\n";
  EXPECT_LT(std::abs(below.contact_slip), below.creep_velocity * 0.2);
  EXPECT_NEAR(above.acceleration, g * (std::sin(28 * deg) - 0.5 * std::cos(28 * deg)),
              0.05 * g * (std::sin(28 * deg) - 0.5 * std::cos(28 * deg)));
}

// A fast stab: the sphere driven 5 mm into the top at 1 m/s, 1 mm per 1 ms step, far more than the contact gap.
// Nodes it outran are put back outside before each step (counted), and after every step no node is inside. (The
// sphere, 6 mm across, is about an element wide: between nodes it passes through the body; only nodes are kept out.)
TEST(Simulation, AFastStabNeverLeavesANodeInsideTheTool) {
  const calibrate::CalibratedModel m = cylinder("any-nu-tet");
  const double top = m.mesh.nodes.col(2).maxCoeff(), radius = 0.003;
  SimulationOptions o;
  o.simulator.integrator = Integrator::kImplicitEuler;
  o.dynamics.dt = 1e-3;
  o.steps = 25;
  o.tool = std::make_shared<contact::RigidTool>(contact::ToolShape::kSphere, radius);
  o.tool_path = contact::ToolPath({{0.0, {Vec3(0.0, 0.0, top + radius), Mat3::Identity()}},
                                   {0.005, {Vec3(0.0, 0.0, top + radius - 0.005), Mat3::Identity()}}});
  const SimulationSummary s = simulate(m, o, [](int, double, const VecX&, const VecX&) {});
  EXPECT_GT(s.smallest_gap, 0.0);
  EXPECT_GT(s.pushed_nodes, 0);
  ASSERT_EQ(s.tool_force.size(), 25u);  // every step completed: no element inverted, nothing entered the tool
}

TEST(Simulation, RefusesAToolWithoutAPath) {
  SimulationOptions o;
  o.tool = std::make_shared<contact::RigidTool>(contact::ToolShape::kSphere, 0.005);
  EXPECT_THROW(simulate(cylinder(), o, [](int, double, const VecX&, const VecX&) {}), InvalidArgument);
  EXPECT_THROW(contact::ToolPath({{0.1, {}}, {0.1, {}}}), InvalidArgument);
}

}  // namespace
}  // namespace hooke::solve
