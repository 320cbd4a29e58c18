// Multirate haptics: the force a 1 kHz haptic loop renders from the local model (secant, condensed or no stiffness)
// of a body deformed at 100 Hz or 33 Hz against the same drag simulated at 1 kHz throughout (the schedule in simulated
// time, deterministic), and the two real threads (HapticLoop beside PhysicsLoop) holding a dragged probe against the
// static equilibrium.
#include <gtest/gtest.h>

#include <chrono>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/contact/contact_block.hpp>
#include <hooke/core/error.hpp>
#include <hooke/interactive/haptic_loop.hpp>
#include <hooke/interactive/local_contact.hpp>
#include <hooke/interactive/multirate.hpp>
#include <hooke/model/problem.hpp>
#include <hooke/model/support.hpp>
#include <hooke/solve/tool_press.hpp>
#include <iostream>
#include <thread>

#include "interactive/support.hpp"

namespace hooke::interactive {
namespace {

LiveSimulation grabbed(const mesh::Mesh& m, double dt, HapticStiffness k = HapticStiffness::kSecant,
                       bool curvature = true) {
  LiveSettings s = settings("any-nu-tet", 0.45);
  s.dynamics.damping_mass = 20.0;
  s.dynamics.dt = dt;
  s.haptic_stiffness = k;
  s.haptic_curvature = curvature;
  s.simulator.quasi_newton.tolerance = kDeformationTolerance;
  LiveSimulation sim(m, s);
  sim.grab({top_node(m)});
  return sim;
}

// The tests' drag (2 mm along x over 0.5 s, 0.7 s in all) and its full-rate reference at 1 kHz.
struct Drag {
  mesh::Mesh m = cylinder();
  DeviceDrag device{Vec3(1.0, 0.0, 0.0), 2e-3, 0.5};
  double duration = 0.7;
  ForceTrace reference;
  Drag() {
    LiveSimulation full = grabbed(m, 1e-3);
    reference = full_rate_force(full, device, duration);
  }
};

TEST(Multirate, ForceWithinFivePercentOfTheFullRateDrag) {
  const Drag drag;
  const auto& [m, device, duration, reference] = drag;
  for (const double deformation_dt : {0.01, 0.03}) {
    double errors[3] = {0.0, 0.0, 0.0};
    for (const HapticStiffness k : {HapticStiffness::kNone, HapticStiffness::kCondensed, HapticStiffness::kSecant}) {
      LiveSimulation sim = grabbed(m, deformation_dt, k, false);  // the linear models (curved: the next test)
      const ForceTrace haptic = multirate_force(sim, device, duration, 1e-3);
      ASSERT_EQ(haptic.time.size(), reference.time.size());
      errors[static_cast<int>(k)] = relative_force_error(haptic, reference);
    }
    std::cout << "[multirate] deformation every " << 1e3 * deformation_dt << " ms, haptics at 1 kHz: force off the "
              << "full-rate run's by (relative to its largest) " << errors[2] << " with the secant stiffness, "
              << errors[1] << " with the condensed one, " << errors[0] << " with the force held\n";
    for (const int k : {1, 2}) {
      EXPECT_LT(errors[k], 0.05);
      EXPECT_LT(errors[k], 0.5 * errors[0]);  // the stiffness carries the force between the steps
    }
    // The secant starts from the condensed stiffness and learns the dynamic response from there: the longer the
    // step, the more that start matters (from zero it was 0.036 at 30 ms, three times the condensed one's error).
    if (deformation_dt > 0.02) {
      EXPECT_LT(errors[2], errors[1]);
    }
  }
  LiveSimulation sim = grabbed(m, 0.0025);
  EXPECT_THROW(multirate_force(sim, device, duration, 1e-3), InvalidArgument);  // not a whole multiple
}

// A deformation step as long as half the drag: the linear local model misses the body's stiffening over the
// offsets it extrapolates to, the curved one (the condensed energy's third derivative at the grab) follows it.
TEST(Multirate, TheCurvatureCarriesTheForceOverLongDeformationSteps) {
  const Drag drag;
  const auto& [m, device, duration, reference] = drag;
  for (const double deformation_dt : {0.1, 0.25}) {
    double errors[2][2];  // [curvature][secant]
    for (const bool curvature : {false, true})
      for (const HapticStiffness k : {HapticStiffness::kCondensed, HapticStiffness::kSecant}) {
        LiveSimulation sim = grabbed(m, deformation_dt, k, curvature);
        errors[curvature][k == HapticStiffness::kSecant] =
            relative_force_error(multirate_force(sim, device, duration, 1e-3), reference);
      }
    std::cout << "[multirate] deformation every " << 1e3 * deformation_dt << " ms: force error linear / curved, "
              << "condensed " << errors[0][0] << " / " << errors[1][0] << ", secant " << errors[0][1] << " / "
              << errors[1][1] << "\n";
    for (const int secant : {0, 1}) {
      EXPECT_LT(errors[1][secant], 0.05);
      EXPECT_LT(errors[1][secant], 0.7 * errors[0][secant]);
    }
  }
}

// The curved model's render: f0 - K d - T(d, d) / 2, written out term by term.
TEST(HapticModel, RendersTheSecondOrderTerm) {
  HapticModel h;
  h.grabbed = true;
  h.offset = Vec3(1e-3, 0.0, -2e-3);
  h.force = Vec3(0.1, -0.2, 0.3);
  h.stiffness = (MatX(3, 3) << 30, 1, 2, 1, 20, 3, 2, 3, 25).finished();
  h.curvature = MatX::Zero(3, 9);
  for (int c = 0; c < 3; ++c)
    for (int a = 0; a < 3; ++a)
      for (int b = a; b < 3; ++b) h.curvature(c, 3 * a + b) = h.curvature(c, 3 * b + a) = 100.0 * (c + 1) + 10 * a + b;
  const Vec3 u(4e-3, 1e-3, 2e-3), d = u - Vec3(h.offset);
  Vec3 expected = Vec3(h.force) - h.stiffness * d;
  for (int c = 0; c < 3; ++c)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) expected(c) -= 0.5 * h.curvature(c, 3 * a + b) * d(a) * d(b);
  EXPECT_LT((h.render(u) - expected).norm(), 1e-15);
  const MatX shift = curvature_along(h.curvature, d);
  for (int c = 0; c < 3; ++c)
    for (int a = 0; a < 3; ++a) EXPECT_DOUBLE_EQ(shift(c, a), h.curvature.row(c).segment(3 * a, 3).dot(d));
  h.curvature.resize(0, 0);  // linear
  EXPECT_LT((h.render(u) - (Vec3(h.force) - h.stiffness * d)).norm(), 1e-15);
}

// At the grab, before any step has given the secant a pair, it is the condensed stiffness.
TEST(Multirate, TheSecantStiffnessStartsFromTheCondensedOne) {
  const mesh::Mesh m = cylinder();
  LiveSimulation secant = grabbed(m, 0.01, HapticStiffness::kSecant);
  LiveSimulation condensed = grabbed(m, 0.01, HapticStiffness::kCondensed);
  const MatX k = condensed.haptic_model().stiffness;
  EXPECT_GT(k.norm(), 0.0);
  EXPECT_EQ(secant.haptic_model().stiffness, k);
}

// Runs both loops for 1.5 s of simulated time at 100 Hz (150 steps; a loaded or sanitized build may need more wall
// time for them, up to 2 minutes), then stops them.
void run_for_150_steps(PhysicsLoop& physics, HapticLoop& haptics) {
  physics.start();
  haptics.start();
  const auto start = std::chrono::steady_clock::now();
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  while (physics.stats().steps < 150 && std::chrono::steady_clock::now() - start < std::chrono::seconds(120))
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  haptics.stop();
  physics.stop();
}

// The real thing: the haptic thread at 1 kHz beside the physics thread at 100 Hz, a scripted device dragging the
// probe 1 mm over 0.2 s and holding it. After it settles the rendered force is the static equilibrium's holding
// force (within 5 %), and both loops reported what they did.
TEST(HapticLoop, RendersTheHoldingForceBesideTheDeformation) {
  const mesh::Mesh m = cylinder();
  LiveSettings s = settings("any-nu-tet", 0.45);
  s.dynamics.damping_mass = 60.0;
  s.dynamics.dt = 0.01;
  LiveSimulation sim(m, s);
  const int node = top_node(m);
  sim.grab({node});
  const calibrate::CalibratedModel model = sim.model();
  const std::vector<int> clamped = sim.clamped_nodes();
  PhysicsLoop physics(std::move(sim), true);
  const DeviceDrag drag{Vec3(1.0, 0.0, 0.0), 1e-3, 0.2};
  HapticLoop haptics(
      physics, [&](double t) { return drag.at(t); }, 1000.0, true);
  run_for_150_steps(physics, haptics);
  const HapticStats h = haptics.stats();
  const PhysicsStats p = physics.stats();
  std::cout << "[haptics] " << h.ticks << " ticks, " << h.achieved_rate << " Hz, period median " << h.period_ms_median
            << " ms p99 " << h.period_ms_p99 << " ms, tick p99 " << h.tick_ms_p99 << " ms; " << h.models
            << " deformation models (" << h.model_rate << " Hz), physics " << p.achieved_rate << " Hz\n";
  EXPECT_TRUE(p.error.empty()) << p.error;
  EXPECT_GT(h.ticks, 100);
  EXPECT_GT(h.models, 10);
  const ForceTrace trace = haptics.trace();
  ASSERT_EQ(static_cast<long>(trace.time.size()), h.ticks);
  const VecX target = m.nodes.row(node).transpose() + Vec3(1e-3, 0.0, 0.0);
  const ProbeEquilibrium eq = probe_equilibrium(model, clamped, {node}, target, false);
  const VecX felt = haptics.force();
  EXPECT_LT((felt - eq.holding_force).norm(), 0.05 * eq.holding_force.norm())
      << "felt " << felt.transpose() << ", holding " << eq.holding_force.transpose();
}

// A sphere (5 mm) pressed 3 mm into the top of the cylinder over 0.5 s, held 0.2 s: the force a 1 kHz loop renders
// from the tool's local contact model (the nodes near the sphere, their compliance and the barrier), the body deformed
// every 10 or 20 ms, against the same press simulated at 1 kHz throughout; and with the force held between steps.
LiveSimulation pressed(const mesh::Mesh& m, double dt, HapticStiffness k) {
  LiveSettings s = settings("any-nu-tet", 0.45);
  s.dynamics.damping_mass = 20.0;
  s.dynamics.dt = dt;
  s.haptic_stiffness = k;
  s.simulator.quasi_newton.tolerance = kDeformationTolerance;
  LiveSimulation sim(m, s);
  sim.set_tool("sphere:0.005", {Vec3(0.0, 0.0, m.nodes.col(2).maxCoeff() + 0.005 + 2e-4), Mat3::Identity()});
  return sim;
}

TEST(Multirate, APressingToolsForceWithinFivePercentOfTheFullRatePress) {
  const mesh::Mesh m = cylinder();
  const DeviceDrag device{Vec3(0.0, 0.0, -1.0), 3e-3, 0.5};
  const double duration = 0.7;
  LiveSimulation full = pressed(m, 1e-3, HapticStiffness::kSecant);
  const ForceTrace reference = full_rate_force(full, device, duration);
  const double largest = reference.force.rowwise().norm().maxCoeff();
  EXPECT_GT(reference.force.col(2).maxCoeff(), 0.05);  // the body pushes the sphere up
  for (const double deformation_dt : {0.01, 0.02}) {
    double errors[2];
    for (const HapticStiffness k : {HapticStiffness::kNone, HapticStiffness::kSecant}) {
      LiveSimulation sim = pressed(m, deformation_dt, k);
      const ForceTrace haptic = multirate_force(sim, device, duration, 1e-3);
      ASSERT_EQ(haptic.time.size(), reference.time.size());
      errors[k == HapticStiffness::kNone ? 0 : 1] = relative_force_error(haptic, reference);
    }
    std::cout << "[multirate press] deformation every " << 1e3 * deformation_dt << " ms, haptics at 1 kHz: force off "
              << "the full-rate press's by " << errors[1] << " of its largest (" << largest << " N) from the local "
              << "contact model, " << errors[0] << " with the force held\n";
    EXPECT_LT(errors[1], 0.05);
    EXPECT_LT(errors[1], 0.5 * errors[0]);
  }
}

// One node of compliance c (isotropic, m/N) resting at the gap d0 under a plane, which holds it down with f0 =
// kappa |b'(d0)|, pressed s further: the node sinks by c (f - f0) while the barrier's force f = kappa |b'(d)| holds it
// at the gap d = d0 - s + c (f - f0); that scalar equation solved by bisection is the local model's force.
TEST(LocalContact, OneNodeUnderAPlaneBalancesItsComplianceAndTheBarrier) {
  const double c = 1e-3, kappa = 50.0, dhat = 1e-4, d0 = 5e-5;
  contact::RigidTool plane(contact::ToolShape::kHalfSpace);
  plane.set_pose({Vec3(0.0, 0.0, 1.0 + d0), contact::rotation_to(Vec3(0.0, 0.0, -1.0))});  // solid above z = 1 + d0
  const double f0 = kappa * std::abs(contact::barrier(d0, dhat).slope);
  const LocalContact local(plane, Vec3(0.0, 0.0, 1.0), (VecX(1) << kappa).finished(), dhat, c * MatX::Identity(3, 3),
                           Vec3(0.0, 0.0, f0));
  // At the step's pose: the step's force.
  EXPECT_NEAR(local.force(plane.pose()).z(), f0, 1e-12);
  for (const double s : {2e-5, 1e-4, 3e-4}) {
    double lo = 1e-12, hi = dhat;  // the gap d: c kappa |b'(d)| - (d - d0 + s) decreases in d
    for (int k = 0; k < 200; ++k) {
      const double d = 0.5 * (lo + hi);
      (c * (kappa * std::abs(contact::barrier(d, dhat).slope) - f0) > d - d0 + s ? lo : hi) = d;
    }
    const double f = kappa * std::abs(contact::barrier(0.5 * (lo + hi), dhat).slope);
    int touching = 0;
    const Vec3 rendered = local.force({Vec3(0.0, 0.0, 1.0 + d0 - s), plane.pose().rotation}, &touching);
    EXPECT_NEAR(rendered.z(), f, 1e-3 * f) << "pressed " << s << " m";
    EXPECT_NEAR(rendered.head<2>().norm(), 0.0, 1e-12);
    EXPECT_EQ(touching, 1);
  }
  // Lifted away: no force.
  EXPECT_LT(local.force({Vec3(0.0, 0.0, 1.0 + 2.0 * dhat), plane.pose().rotation}).norm(), 1e-12);
}

// The real threads with a tool: the haptic thread at 1 kHz drives a sphere 2 mm into the top over 0.2 s and holds it,
// the physics deforms at 100 Hz. After it settles the rendered force is the quasi-static press's at that pose
// (solve::press_quasi_statically on a problem assembled here), within 5 %.
TEST(HapticLoop, RendersAPressingToolsForceBesideTheDeformation) {
  const mesh::Mesh m = cylinder();
  const double top = m.nodes.col(2).maxCoeff(), r = 0.005;
  LiveSimulation sim = pressed(m, 0.01, HapticStiffness::kSecant);
  const calibrate::CalibratedModel model = sim.model();
  const std::vector<int> clamped = sim.clamped_nodes();
  PhysicsLoop physics(std::move(sim), true);
  const DeviceDrag press{Vec3(0.0, 0.0, -1.0), 2.2e-3, 0.2};  // from 0.2 mm above: 2 mm deep
  HapticLoop haptics(
      physics, [&](double t) { return press.at(t); }, 1000.0, true);
  run_for_150_steps(physics, haptics);
  const HapticStats h = haptics.stats();
  const PhysicsStats p = physics.stats();
  std::cout << "[haptics, tool] " << h.ticks << " ticks, period p99 " << h.period_ms_p99 << " ms, tick median "
            << h.tick_ms_median << " ms p99 " << h.tick_ms_p99 << " ms; " << h.models << " deformation models\n";
  EXPECT_TRUE(p.error.empty()) << p.error;
  EXPECT_GT(h.models, 10);

  auto tool = std::make_shared<contact::RigidTool>(contact::ToolShape::kSphere, r);
  const calibrate::BuiltModel built = calibrate::build_model(model);
  auto block = contact::boundary_contact(model.mesh, model.material.youngs_modulus, tool);
  const contact::ContactBlock& contact = *block;
  built.model->add(std::move(block));
  model::Problem problem = model::make_problem(built.model);
  model::fix_nodes(problem, clamped);
  std::vector<contact::Pose> poses;
  for (int k = 0; k <= 5; ++k) poses.push_back({Vec3(0.0, 0.0, top + r + 2e-4 - 0.44e-3 * k), Mat3::Identity()});
  tool->set_pose(poses[0]);
  const Vec3 still = solve::press_quasi_statically(problem, contact, *tool, poses).back().tool_force;
  const VecX felt = haptics.force();
  ASSERT_EQ(felt.size(), 3);
  EXPECT_GT(still.z(), 0.05);
  EXPECT_LT((felt - still).norm(), 0.05 * still.norm())
      << "felt " << felt.transpose() << ", static " << still.transpose();
}

}  // namespace
}  // namespace hooke::interactive
