#pragma once
/// The multirate haptics benchmark behind `hooke bench --haptics`: on the benchmark cylinders
/// (experiments::benchmark_cylinder, the top's centre held: experiments::benchmark_probe_nodes), a device drags the
/// probe along x (or, with a tool, presses a sphere into the top's centre) (smoothstep ramp, then held) while the body
/// deforms at its own rate and a haptic loop renders the force at 1 kHz. Measured per mesh: the haptic loop's achieved
/// rate, period and tick percentiles and the deformation's rate (real threads, wall time), and the rendered force
/// against the same drag simulated at the haptic rate throughout (the full-rate reference), both on the deterministic
/// schedule and from the real-time run.
#include <hooke/interactive/haptic_model.hpp>
#include <hooke/solve/simulator.hpp>
#include <string>
#include <vector>

namespace hooke::interactive {

struct HapticsBenchmarkOptions {
  std::vector<int> sizes = {0, 1};    ///< benchmark cylinders 0, 1, 2 (1 089, 11 425, 103 066 nodes)
  std::string method = "any-nu-tet";  ///< calibration method
  double poisson = 0.45;              ///< nu
  double haptic_rate = 1000.0;        ///< Hz
  double drag = 2e-3;                 ///< device travel along x, m
  /// > 0: instead of the grab, a sphere of this radius (m) over the top's centre, 0.1 mm above it, pressed by the
  /// device `tool_press` x the height down along -z (the force rendered from its local contact model, LocalContact)
  double tool_radius = 0.0;
  double tool_press = 0.1;
  double ramp = 1.0;           ///< s of smoothstep ramp
  double hold = 0.3;           ///< s held after it
  double damping_mass = 20.0;  ///< Rayleigh alpha, 1/s
  HapticStiffness stiffness = HapticStiffness::kSecant;
  bool curvature = true;  ///< LiveSettings::haptic_curvature
  /// the deformation's integrator (and the reference's): quasi-newton at kDeformationTolerance by default
  solve::SimulatorOptions simulator = [] {
    solve::SimulatorOptions s;
    s.quasi_newton.tolerance = kDeformationTolerance;
    return s;
  }();
  /// the deformation's step, s; 0: measured, 1.25 x the median wall time of 5 steps of 40 ms during the ramp's
  /// fastest drag, rounded up to a haptic period (a longer step may take longer: the real-time run says)
  double deformation_dt = 0.0;
  /// the full-rate reference is skipped (errors reported as -1, with a note) when 5 measured steps at the haptic
  /// rate say it would take longer than this, s
  double reference_budget = 900.0;
};

struct HapticsBenchmarkRow {
  int nodes = 0;
  double deformation_dt = 0.0;       ///< s
  double deformation_step_ms = 0.0;  ///< median wall time of a deformation step (real-time run), ms
  double deformation_rate = 0.0;     ///< local models received per wall second, Hz
  double haptic_rate = 0.0;          ///< ticks per wall second, Hz
  double haptic_period_ms_p99 = 0.0, haptic_tick_ms_p99 = 0.0;  ///< ms
  /// max |f - f_reference| / max |f_reference|: the deterministic schedule, the real-time run (-1: not measured)
  double schedule_error = -1.0, realtime_error = -1.0;
  double held_error = -1.0;        ///< the schedule with the force held (no stiffness), for comparison
  double reference_seconds = 0.0;  ///< wall time of the full-rate reference
};

struct HapticsBenchmarkReport {
  std::vector<HapticsBenchmarkRow> rows;
  std::vector<std::string> notes;
};

/// Runs it. @throws InvalidArgument for a size outside 0..2 or options out of range
HapticsBenchmarkReport run_haptics_benchmark(const HapticsBenchmarkOptions& options);

/// The report as a Markdown table.
std::string haptics_benchmark_markdown(const HapticsBenchmarkOptions& options, const HapticsBenchmarkReport& report);

}  // namespace hooke::interactive
