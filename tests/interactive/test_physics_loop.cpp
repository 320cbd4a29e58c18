// The physics thread (interactive::PhysicsLoop) from the front end's side: a script's drawing commands arrive with
// the state of their time, a bad command is reported, the rate shown is the one achieved, every member is served
// within a step or two while the physics runs flat out, and commands may call the loop back. Built and run under
// ThreadSanitizer by scripts/test.sh (the tsan preset).
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <hooke/core/error.hpp>
#include <hooke/core/quantile.hpp>
#include <hooke/interactive/guarded.hpp>
#include <hooke/interactive/latest_job.hpp>
#include <hooke/interactive/physics_loop.hpp>
#include <iostream>
#include <thread>

#include "interactive/support.hpp"

namespace hooke::interactive {
namespace {

// Runs `loop` until its script is carried out, taking the drawing commands as a front end does; `on_drawing` sees
// each command with the snapshot drawing_commands() gave with it.
template <typename OnDrawing>
void drive_script(PhysicsLoop& loop, OnDrawing on_drawing) {
  Snapshot snap;
  for (int wait = 0; wait < 100000 && !loop.script_finished(); ++wait) {
    const std::vector<ScriptCommand> commands = loop.drawing_commands(snap);
    for (const ScriptCommand& c : commands) on_drawing(c, snap);
    if (!commands.empty()) loop.drawing_done();
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
}

TEST(PhysicsLoop, DrawingCommandsComeWithTheStateOfTheirTime) {
  const mesh::Mesh m = cylinder();
  const std::string script = "0 grab " + std::to_string(top_node(m)) +
                             "\n"
                             "0.001 drag 0.001 0 0 over 0.05\n"
                             "0.06 screenshot a.png\n"
                             "0.06 set poisson 0.2\n"
                             "0.07 screenshot b.png\n"
                             "0.08 release\n"
                             "0.1 quit\n";
  PhysicsLoop loop(LiveSimulation(m, settings()), false);
  loop.set_script(parse_script(script, "test"));
  loop.start();
  std::vector<ScriptCommand> seen;
  std::vector<double> times, offsets, nus;
  drive_script(loop, [&](const ScriptCommand& c, const Snapshot& snap) {
    seen.push_back(c);
    times.push_back(snap.stats.sim_time);
    offsets.push_back(snap.probe_offset.norm());
    nus.push_back(snap.settings.material.poisson_ratio);
  });
  EXPECT_THROW(loop.set_script({}), InvalidArgument);  // not while the thread runs
  loop.stop();
  ASSERT_EQ(seen.size(), 3u);
  EXPECT_EQ(seen[0].action, ScriptAction::kScreenshot);
  EXPECT_EQ(seen[1].action, ScriptAction::kScreenshot);
  EXPECT_EQ(seen[2].action, ScriptAction::kQuit);
  // Each command's state is the one at its time: at 0.06 s dragged by 1 mm with nu still 0.3, at 0.07 s with 0.2.
  EXPECT_NEAR(times[0], 0.06, 1e-3);
  EXPECT_NEAR(offsets[0], 1e-3, 1e-12);
  EXPECT_EQ(nus[0], 0.3);
  EXPECT_NEAR(times[1], 0.07, 1e-3);
  EXPECT_EQ(nus[1], 0.2);
  EXPECT_NEAR(times[2], 0.1, 1e-3);
  Snapshot snap;
  loop.snapshot(snap);
  EXPECT_TRUE(snap.grabbed.empty());
  EXPECT_TRUE(snap.stats.error.empty()) << snap.stats.error;
  EXPECT_GE(snap.stats.steps, 100);
}

// A scripted tool (the acceptance's press, on a small cylinder): at the screenshot it sits 3 mm into the top, pushed
// back by the body with no node inside it; the snapshot carries it for the front end.
TEST(PhysicsLoop, AScriptedToolPressesAndTheSnapshotCarriesItsForce) {
  const mesh::Mesh m = cylinder();
  const double top = m.nodes.col(2).maxCoeff();
  char script[256];
  std::snprintf(script, sizeof script,
                "0 tool sphere:0.005 0 0 %.9g\n0 move-tool 0 0 %.9g over 0.1\n0.2 screenshot a.png\n0.2 quit\n",
                top + 0.006, top + 0.002);
  LiveSettings s = settings("any-nu-tet", 0.45);
  s.simulator.integrator = solve::Integrator::kImplicitEuler;
  PhysicsLoop loop(LiveSimulation(m, s), false);
  loop.set_script(parse_script(script, "press.txt"));
  loop.start();
  std::vector<Snapshot> seen;
  drive_script(loop, [&](const ScriptCommand&, const Snapshot& snap) { seen.push_back(snap); });
  loop.stop();
  ASSERT_EQ(seen.size(), 2u);
  ASSERT_TRUE(seen[0].tool);
  EXPECT_TRUE(seen[0].stats.error.empty()) << seen[0].stats.error;
  EXPECT_NEAR(seen[0].tool->tool.pose().position.z(), top + 0.002, 1e-12);
  EXPECT_GT(seen[0].tool->force.z(), 0.01);
  EXPECT_GT(seen[0].tool->smallest_gap, 0.0);
  EXPECT_GT(seen[0].tool->active, 0);
}

TEST(PhysicsLoop, WithoutAFrontEndDrawingCommandsAreSkipped) {
  PhysicsLoop loop(LiveSimulation(cylinder(), settings()), false);
  loop.set_script(parse_script("0.01 screenshot a.png\n0.02 quit\n", "test"), false);
  loop.start();
  for (int k = 0; k < 10000 && !loop.script_finished(); ++k)
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  EXPECT_TRUE(loop.script_finished());
  Snapshot snap;
  EXPECT_TRUE(loop.drawing_commands(snap).empty());
  loop.stop();
}

TEST(PhysicsLoop, ABadCommandIsReportedNotThrown) {
  PhysicsLoop loop(LiveSimulation(cylinder(), settings()), false);
  loop.post([](LiveSimulation& sim) {
    LiveSettings s = sim.settings();
    s.model.method = "no-such-method";
    sim.apply(s);
  });
  loop.start();
  for (int k = 0; k < 1000 && loop.stats().error.empty(); ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  loop.stop();
  EXPECT_NE(loop.stats().error.find("no-such-method"), std::string::npos) << loop.stats().error;
  EXPECT_GT(loop.stats().steps, 0);
}

// The rate shown is steps completed per wall second: a loop whose steps take longer than their period (dt = 10 us,
// a 100 kHz target) reports the rate it achieves, measured from outside, and says it is behind; at dt = 1 ms and
// paced it never reports more than its target.
TEST(PhysicsLoop, AchievedRateIsStepsPerWallSecond) {
  {
    PhysicsLoop loop(LiveSimulation(cylinder(), settings()), true);
    loop.start();
    // At least 300 ms and 20 steps (a loaded CI core, or a sanitizer build, may take long for the first ones).
    const auto start = std::chrono::steady_clock::now();
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    while (loop.stats().steps < 20 && std::chrono::steady_clock::now() - start < std::chrono::seconds(60))
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    const PhysicsStats s = loop.stats();
    loop.stop();
    EXPECT_LE(s.achieved_rate, 1.001 * s.target_rate);
    EXPECT_GE(s.steps, 20);
  }
  LiveSettings fast = settings();
  fast.dynamics.dt = 1e-5;
  PhysicsLoop loop(LiveSimulation(cylinder(), fast), true);
  loop.start();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const auto t0 = std::chrono::steady_clock::now();
  const long steps0 = loop.stats().steps;
  std::this_thread::sleep_for(std::chrono::milliseconds(600));
  const PhysicsStats slow = loop.stats();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  loop.stop();
  const double measured = static_cast<double>(slow.steps - steps0) / seconds;
  std::cout << "[rate] dt 10 us: " << measured << " steps per wall second, reported " << slow.achieved_rate
            << " Hz (target " << slow.target_rate << "), median step " << slow.step_ms_median << " ms\n";
  ASSERT_LT(measured, 0.9 * slow.target_rate) << "the steps were not slower than their period";
  EXPECT_TRUE(slow.behind);
  EXPECT_NEAR(slow.achieved_rate, measured, 0.35 * measured);
}

// Ends the test binary when `body` has not returned within `seconds` (a deadlock would otherwise hang the suite).
template <typename Body>
void within(double seconds, const char* what, Body body) {
  std::atomic<bool> done{false};
  std::thread watchdog([&] {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (!done && std::chrono::steady_clock::now() < until) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (!done) {
      std::cerr << "deadlock: " << what << " did not return within " << seconds << " s\n";
      std::_Exit(1);
    }
  });
  body();
  done = true;
  watchdog.join();
}

// While the physics runs flat out (no pacing), each member the front end calls is served within a few steps: the
// 99th percentile over 500 calls of the steps the physics made during one call is at most 10 (a descheduled test
// thread may see more now and then). With a lock the physics takes again right after each step, stats() and post()
// waited 54 to 1 135 steps at that percentile or beyond (measured before the fix; 0 and 1 after).
TEST(PhysicsLoop, EveryMemberIsServedWithinAStepOrTwo) {
  PhysicsLoop loop(LiveSimulation(cylinder(), settings()), false);
  loop.start();
  while (loop.stats().steps < 20) std::this_thread::yield();
  const double dt = settings().dynamics.dt;
  std::vector<double> stats_steps, post_steps, pause_steps, snapshot_steps;
  Snapshot snap;
  for (int k = 0; k < 500; ++k) {
    long a = loop.stats().steps;
    long b = loop.stats().steps;
    stats_steps.push_back(static_cast<double>(b - a));
    a = b;
    loop.set_paused(false);
    b = loop.stats().steps;
    pause_steps.push_back(static_cast<double>(b - a) / 2.0);  // two calls
    loop.snapshot(snap);
    a = snap.stats.steps;
    loop.snapshot(snap);
    snapshot_steps.push_back(static_cast<double>(snap.stats.steps - a));
    // A command posted now runs before the physics' next step or the one after.
    std::atomic<double> ran_at{-1.0};
    loop.snapshot(snap);
    const double posted_at = snap.stats.sim_time;
    loop.post([&](LiveSimulation& sim) { ran_at = sim.time(); });
    while (ran_at < 0.0) std::this_thread::yield();
    post_steps.push_back((ran_at - posted_at) / dt);
  }
  loop.stop();
  const auto p99 = [](std::vector<double> v) { return quantile(v, 0.99); };
  std::cout << "[served] 99th percentile of the steps during stats() " << p99(stats_steps)
            << ", set_paused() + stats() " << p99(pause_steps) << ", snapshot() " << p99(snapshot_steps)
            << ", post() to run " << p99(post_steps) << "\n";
  EXPECT_LE(p99(stats_steps), 10.0);
  EXPECT_LE(p99(pause_steps), 10.0);
  EXPECT_LE(p99(snapshot_steps), 10.0);
  EXPECT_LE(p99(post_steps), 10.0 + 1e-9);
}

// A posted command and a with() command may call the loop back (stats, snapshot, post, with, paused) without
// deadlocking; the nested with() runs at once.
TEST(PhysicsLoop, CommandsMayCallTheLoopBack) {
  PhysicsLoop loop(LiveSimulation(cylinder(), settings()), false);
  loop.start();
  std::atomic<int> from_command{0}, nested_post{0};
  within(30.0, "calls from a posted command", [&] {
    loop.post([&](LiveSimulation&) {
      Snapshot s;
      loop.snapshot(s);
      (void)loop.stats();
      (void)loop.paused();
      loop.with([&](const LiveSimulation& sim) { from_command += sim.time() >= 0.0 ? 1 : 0; });
      loop.post([&](LiveSimulation&) { ++nested_post; });
      ++from_command;
    });
    while (from_command < 2 || nested_post < 1) std::this_thread::yield();
  });
  int from_with = 0;
  within(30.0, "calls from a with() command", [&] {
    loop.with([&](const LiveSimulation& sim) {
      Snapshot s;
      loop.snapshot(s);
      (void)loop.stats();
      loop.set_paused(false);
      loop.with([&](const LiveSimulation& inner) { from_with += &inner == &sim ? 1 : 0; });
      loop.post([](LiveSimulation&) {});
      ++from_with;
    });
  });
  loop.stop();
  EXPECT_EQ(from_command.load(), 2);
  EXPECT_EQ(nested_post.load(), 1);
  EXPECT_EQ(from_with, 2);
  EXPECT_TRUE(loop.stats().error.empty()) << loop.stats().error;
}

// The front end's whole traffic at once while the physics runs (the ThreadSanitizer pass's main case): snapshots,
// grabs and drags, live recalibration, the model copied for the FEM ghost solved in the background, pauses, stats.
TEST(PhysicsLoop, ApplyGrabAndGhostWhileRunning) {
  const mesh::Mesh m = cylinder();
  const int node = top_node(m);
  PhysicsLoop loop(LiveSimulation(m, settings("any-nu-tet", 0.3)), false);
  loop.start();
  LatestJob<ProbeEquilibrium> ghost;
  Snapshot snap;
  int ghosts = 0;
  long last_model = 0;
  for (int k = 0; k < 40; ++k) {
    loop.snapshot(snap);
    if (k % 10 == 0) loop.post([node](LiveSimulation& sim) { sim.grab({node}); });
    const VecX offset = Vec3(1e-4 * (k % 10), 0.0, 0.0);
    loop.post([offset](LiveSimulation& sim) { sim.drag(offset); });
    if (k % 8 == 3) {
      const double nu = k % 16 == 3 ? 0.45 : 0.3;
      loop.post([nu](LiveSimulation& sim) {
        LiveSettings s = sim.settings();
        s.material.poisson_ratio = nu;
        sim.apply(s);
      });
    }
    if (k % 5 == 0) {
      calibrate::CalibratedModel model;
      std::vector<int> clamped;
      loop.with([&](const LiveSimulation& sim) {
        model = sim.model();
        clamped = sim.clamped_nodes();
      });
      VecX target = m.nodes.row(node).transpose() + offset;
      ghost.submit([model = std::move(model), clamped, node, target] {
        return fem_probe_equilibrium(model, material::Law::kLinear, clamped, {node}, target, false);
      });
    }
    if (std::optional<ProbeEquilibrium> r = ghost.take()) ghosts += r->positions.allFinite() ? 1 : 0;
    if (k % 7 == 0) {
      loop.set_paused(true);
      loop.set_paused(false);
    }
    last_model = std::max(last_model, snap.model_version);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  while (ghost.pending()) {
    if (std::optional<ProbeEquilibrium> r = ghost.take()) ghosts += r->positions.allFinite() ? 1 : 0;
    std::this_thread::yield();
  }
  // The physics keeps stepping through all of that: wait (not a timing assertion: a loaded CI core may be slow) for
  // it to pass 40 steps, which a deadlock or a stuck exchange would never do.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  for (loop.snapshot(snap); snap.stats.steps <= 40 && std::chrono::steady_clock::now() < deadline; loop.snapshot(snap))
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  loop.stop();
  loop.snapshot(snap);
  EXPECT_TRUE(snap.stats.error.empty()) << snap.stats.error;
  EXPECT_GE(snap.model_version, 5);  // every apply recalibrated
  EXPECT_GE(ghosts, 1);
  EXPECT_GT(snap.stats.steps, 40);
}

// Guarded serialises a simulation stepped by one thread and dragged by another (Python's hooke.LiveSimulation with a
// haptic device's thread): every step and every drag happens whole.
TEST(Guarded, OneThreadStepsAnotherDrags) {
  const mesh::Mesh m = cylinder();
  Guarded<LiveSimulation> sim(LiveSimulation(m, settings()));
  const int node = top_node(m);
  sim.with([&](LiveSimulation& s) { s.grab({node}); });
  std::atomic<bool> stepping{true};
  std::thread device([&] {
    for (int k = 0; stepping; ++k) {
      sim.with([&](LiveSimulation& s) { s.drag(Vec3(1e-6 * (k % 1000), 0.0, 0.0)); });
      const VecX x = sim.with([](const LiveSimulation& s) { return s.positions(); });
      ASSERT_TRUE(x.allFinite());
    }
  });
  for (int k = 0; k < 200; ++k) sim.with([](LiveSimulation& s) { s.step(); });
  stepping = false;
  device.join();
  EXPECT_NEAR(sim.with([](const LiveSimulation& s) { return s.time(); }), 200 * settings().dynamics.dt, 1e-12);
}

// A job submitted while an older one runs starts at once (the older one is not waited for) and only the newest
// result is given; a job's exception is rethrown by take().
TEST(LatestJob, SubmitNeverWaitsForAnOlderJob) {
  LatestJob<int> job;
  std::atomic<bool> release{false}, old_timed_out{false};
  job.submit([&] {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (!release && std::chrono::steady_clock::now() < until)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    old_timed_out = !release;
    return 1;
  });
  job.submit([] { return 2; });  // returns while the first one still waits for `release`
  release = true;
  std::optional<int> r;
  while (!(r = job.take())) std::this_thread::yield();
  EXPECT_EQ(*r, 2);
  EXPECT_FALSE(old_timed_out);
  EXPECT_FALSE(job.pending());
  job.submit([]() -> int { throw SolverFailure("did not converge"); });
  for (;;) {
    try {
      if (job.take()) break;
    } catch (const SolverFailure& e) {
      EXPECT_NE(std::string(e.what()).find("did not converge"), std::string::npos);
      break;
    }
    std::this_thread::yield();
  }
  job.run_now([] { return 3; });
  EXPECT_EQ(job.take().value_or(0), 3);
}

}  // namespace
}  // namespace hooke::interactive
