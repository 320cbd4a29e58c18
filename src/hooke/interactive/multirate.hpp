#pragma once
/// Multirate haptics in simulated time (Cavusoglu & Tendick 2000; Mark et al. 1996): the body deforms in steps of
/// deformation_dt while a haptic loop renders the probe force every haptic_dt from the last step's local model
/// (interactive::HapticModel). Deterministic: the schedule a real-time pair of threads follows (HapticLoop), with
/// the latency it has, so that tests and benchmarks can compare it with the same drag simulated at full rate.
///
/// Schedule: deformation step k starts at t_k = k deformation_dt with the device's offset u(t_k), and its model is
/// in use from t_k + deformation_dt (when a real-time step of that length has finished) until the next one. Before
/// the first step has finished, the grab's model is in use (the force at the grab; the condensed stiffness is
/// computed at the grab, the secant one has no pair yet and is zero).
#include <hooke/interactive/live_simulation.hpp>
#include <string>
#include <vector>

namespace hooke::interactive {

/// A device dragging the probe: offset(t) = distance * s(t / ramp) * direction, s the smoothstep 3 x^2 - 2 x^3
/// (clamped to [0, 1]; no jerk at its start), then held.
struct DeviceDrag {
  VecX direction;           ///< unit (dim)
  double distance = 0.0;    ///< m
  double ramp = 1.0;        ///< s (> 0)
  VecX at(double t) const;  ///< m (dim)
};

/// The probe force a run produced, at every haptic tick.
struct ForceTrace {
  std::vector<double> time;  ///< s
  RowMatX force;             ///< N (ticks x dim)
};

/// The device's offset (m, dim) to `sim`: it drives the grab, or, without one, the tool (LiveSimulation::drive_tool).
/// @throws InvalidArgument for an offset of the wrong size or not finite
void apply_device(LiveSimulation& sim, const VecX& offset);
/// The force on what the device drives after the last step, N (dim): the probe's, or the tool's.
VecX device_force(const LiveSimulation& sim);

/// The device drives the grab, or, without one, the tool (LiveSimulation::drive_tool; the force is then the tool's,
/// rendered from its local contact model).
///
/// The reference: `sim` (nodes already grabbed or a tool set; advanced by the run) stepped at its own dt with the
/// device's offset set before every step, for `duration` s; the force after each step, at the step's end time.
ForceTrace full_rate_force(LiveSimulation& sim, const DeviceDrag& device, double duration);

/// The multirate run: `sim` (nodes grabbed or a tool set; advanced by the run; its settings' dt is the deformation
/// step, a multiple of haptic_dt) deformed on the schedule above and rendered every haptic_dt from t = haptic_dt to
/// `duration`.
/// @throws InvalidArgument when dt is not a whole multiple of haptic_dt
ForceTrace multirate_force(LiveSimulation& sim, const DeviceDrag& device, double duration, double haptic_dt);

/// max over the ticks of |a - b| / max over b's ticks of |b|, at the times they share (within 1e-9 s).
/// @throws InvalidArgument when they share no time
double relative_force_error(const ForceTrace& a, const ForceTrace& b);

}  // namespace hooke::interactive
