#include <chrono>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/core/quantile.hpp>
#include <hooke/experiments/dynamics_benchmark.hpp>
#include <hooke/interactive/haptic_loop.hpp>
#include <hooke/interactive/haptics_benchmark.hpp>
#include <hooke/interactive/multirate.hpp>
#include <sstream>
#include <string>
#include <thread>

namespace hooke::interactive {
namespace {

using Clock = std::chrono::steady_clock;

LiveSimulation make_simulation(const mesh::Mesh& m, const HapticsBenchmarkOptions& o, double dt) {
  LiveSettings s;
  s.model.method = o.method;
  s.material = {material::Law::kLinear, 14630.0, o.poisson};
  s.dynamics.damping_mass = o.damping_mass;
  s.haptic_stiffness = o.stiffness;
  s.haptic_curvature = o.curvature;
  s.simulator = o.simulator;
  s.dynamics.dt = dt;
  LiveSimulation sim(m, s);
  if (o.tool_radius > 0.0) {
    const double top = m.nodes.col(2).maxCoeff();
    sim.set_tool("sphere:" + std::to_string(o.tool_radius),
                 {Vec3(0.0, 0.0, top + o.tool_radius + 1e-4), Mat3::Identity()});
  } else {
    sim.grab(experiments::benchmark_probe_nodes(m));
  }
  return sim;
}

// The device: the drag along x, or the tool's press along -z by tool_press x the height.
DeviceDrag device_of(const mesh::Mesh& m, const HapticsBenchmarkOptions& o) {
  if (o.tool_radius > 0.0)
    return {Vec3(0.0, 0.0, -1.0), o.tool_press * (m.nodes.col(2).maxCoeff() - m.nodes.col(2).minCoeff()), o.ramp};
  return {Vec3(1.0, 0.0, 0.0), o.drag, o.ramp};
}

// Median wall time of `steps` steps of `sim` (after one untimed) while the device moves at `speed` m/s along
// `direction`, s.
double median_step(LiveSimulation& sim, int steps, double speed, const VecX& direction) {
  sim.step();
  std::vector<double> t;
  for (int k = 0; k < steps; ++k) {
    apply_device(sim, speed * sim.time() * direction);
    const auto a = Clock::now();
    sim.step();
    t.push_back(std::chrono::duration<double>(Clock::now() - a).count());
  }
  return quantile(t, 0.5);
}

// run(), its solver failure prefixed with the mesh and the run it stopped (the table has several per mesh).
template <class F>
auto in_run(int nodes, const std::string& which, F&& run) {
  try {
    return run();
  } catch (const SolverFailure& e) {
    throw SolverFailure(std::to_string(nodes) + " nodes, " + which + ": " + e.what());
  }
}

// The reference's force at wall time t: its sample nearest t.
double realtime_error(const ForceTrace& haptic, const ForceTrace& reference, double h) {
  double worst = 0.0, scale = 0.0;
  for (Eigen::Index i = 0; i < reference.force.rows(); ++i) scale = std::max(scale, reference.force.row(i).norm());
  for (size_t i = 0; i < haptic.time.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(std::llround(haptic.time[i] / h)) - 1;  // reference[k] is at (k + 1) h
    if (k < 0 || k >= reference.force.rows()) continue;
    worst = std::max(worst, (haptic.force.row(static_cast<Eigen::Index>(i)) - reference.force.row(k)).norm());
  }
  return scale > 0.0 ? worst / scale : worst;
}

}  // namespace

HapticsBenchmarkReport run_haptics_benchmark(const HapticsBenchmarkOptions& o) {
  if (!(o.haptic_rate > 0.0) || !(o.ramp > 0.0) || !(o.hold >= 0.0) || !std::isfinite(o.drag) ||
      !(o.tool_radius >= 0.0) || !(o.tool_press > 0.0 && o.tool_press < 1.0))
    throw InvalidArgument(
        "haptics benchmark: the rate, ramp and hold must be > 0 (hold >= 0), the tool's radius >= 0 and its press "
        "in (0, 1)");
  const double h = 1.0 / o.haptic_rate, duration = o.ramp + o.hold;
  HapticsBenchmarkReport report;
  for (const int size : o.sizes) {
    const mesh::Mesh m = experiments::benchmark_cylinder(size);
    const DeviceDrag device = device_of(m, o);
    HapticsBenchmarkRow row;
    row.nodes = m.node_count();
    // The deformation step: measured unless given.
    double dt = o.deformation_dt;
    const double speed = 1.5 * device.distance / o.ramp;  // the ramp's fastest
    if (!(dt > 0.0)) {
      LiveSimulation probe = make_simulation(m, o, 0.04);
      dt = std::max(h, std::ceil(1.25 * median_step(probe, 5, speed, device.direction) / h) * h);
    }
    row.deformation_dt = dt;
    // The full-rate reference, when affordable.
    ForceTrace reference;
    {
      LiveSimulation full = make_simulation(m, o, h);
      const double estimate = median_step(full, 5, speed, device.direction) * duration / h;
      if (estimate <= o.reference_budget) {
        LiveSimulation fresh = make_simulation(m, o, h);
        const auto t0 = Clock::now();
        reference = in_run(m.node_count(), "the full-rate reference (dt " + std::to_string(1e3 * h) + " ms)",
                           [&] { return full_rate_force(fresh, device, duration); });
        row.reference_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
      } else {
        std::ostringstream note;
        note << m.node_count() << " nodes: no full-rate reference (" << std::llround(duration / h) << " steps of "
             << 1e3 * estimate * h / duration << " ms each: about " << std::llround(estimate)
             << " s, over the budget of " << o.reference_budget << " s)";
        report.notes.push_back(note.str());
      }
    }
    if (!reference.time.empty()) {
      for (const bool held : {false, true}) {
        HapticsBenchmarkOptions oo = o;
        if (held) oo.stiffness = HapticStiffness::kNone;
        LiveSimulation sim = make_simulation(m, oo, dt);
        const double e =
            relative_force_error(in_run(m.node_count(),
                                        std::string(held ? "the held-force" : "the multirate") +
                                            " schedule (deformation dt " + std::to_string(1e3 * dt) + " ms)",
                                        [&] { return multirate_force(sim, device, duration, h); }),
                                 reference);
        (held ? row.held_error : row.schedule_error) = e;
      }
    }
    // The real threads: the deformation paced at its step, the haptic loop at its rate, for the drag's duration.
    {
      LiveSimulation sim = make_simulation(m, o, dt);
      sim.step();  // the first step at a new dt factorises: before the device moves, as a user grabs, then drags
      sim.haptic_model();  // so does the condensed stiffness (kept until the next grab)
      PhysicsLoop physics(std::move(sim), true);
      HapticLoop haptics(
          physics, [&](double t) { return device.at(t); }, o.haptic_rate, true);
      physics.start();
      haptics.start();
      std::this_thread::sleep_for(std::chrono::duration<double>(duration));
      haptics.stop();
      physics.stop();
      const HapticStats hs = haptics.stats();
      const PhysicsStats ps = physics.stats();
      row.haptic_rate = hs.achieved_rate;
      row.haptic_period_ms_p99 = hs.period_ms_p99;
      row.haptic_tick_ms_p99 = hs.tick_ms_p99;
      row.deformation_rate = hs.model_rate;
      row.deformation_step_ms = ps.step_ms_median;
      if (!ps.error.empty()) report.notes.push_back(std::to_string(m.node_count()) + " nodes: " + ps.error);
      if (!reference.time.empty()) row.realtime_error = realtime_error(haptics.trace(), reference, h);
    }
    report.rows.push_back(row);
  }
  return report;
}

std::string haptics_benchmark_markdown(const HapticsBenchmarkOptions& o, const HapticsBenchmarkReport& r) {
  std::ostringstream s;
  const auto num = [](double v, int precision = 3) {
    if (v < 0.0) return std::string("-");
    std::ostringstream t;
    t.precision(precision);
    t << v;
    return t.str();
  };
  s << "| nodes | deformation dt ms | deformation step ms (median) | models/s | haptic Hz | haptic period p99 ms "
       "| haptic tick p99 ms | force error, schedule | force error, real time | force held, schedule "
       "| reference s |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const HapticsBenchmarkRow& w : r.rows)
    s << "| " << w.nodes << " | " << num(1e3 * w.deformation_dt) << " | " << num(w.deformation_step_ms) << " | "
      << num(w.deformation_rate) << " | " << num(w.haptic_rate, 5) << " | " << num(w.haptic_period_ms_p99) << " | "
      << num(w.haptic_tick_ms_p99) << " | " << num(w.schedule_error) << " | " << num(w.realtime_error) << " | "
      << num(w.held_error) << " | " << num(w.reference_seconds) << " |\n";
  s << "\n" << o.method << " at nu " << o.poisson << ", ";
  if (o.tool_radius > 0.0)
    s << "a sphere of radius " << 1e3 * o.tool_radius << " mm pressed " << o.tool_press << " x the height into the top";
  else
    s << "the probe dragged " << 1e3 * o.drag << " mm";
  s << " over " << o.ramp << " s and held " << o.hold
    << " s; force errors relative to the full-rate reference's largest force.\n";
  for (const std::string& n : r.notes) s << "\n- " << n;
  if (!r.notes.empty()) s << "\n";
  return s.str();
}

}  // namespace hooke::interactive
