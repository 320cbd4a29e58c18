#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/interactive/multirate.hpp>

namespace hooke::interactive {

void apply_device(LiveSimulation& sim, const VecX& offset) {
  if (sim.grabbed().empty() && sim.tool())
    sim.drive_tool(offset);
  else
    sim.drag(offset);
}

VecX device_force(const LiveSimulation& sim) {
  if (sim.grabbed().empty() && sim.tool()) return sim.tool()->force;
  return sim.probe_force();
}

VecX DeviceDrag::at(double t) const {
  const double x = std::clamp(t / ramp, 0.0, 1.0);
  return distance * (3.0 * x * x - 2.0 * x * x * x) * direction;
}

ForceTrace full_rate_force(LiveSimulation& sim, const DeviceDrag& device, double duration) {
  const double dt = sim.settings().dynamics.dt;
  const auto steps = static_cast<Eigen::Index>(std::llround(duration / dt));
  ForceTrace out;
  out.force.resize(steps, sim.model().mesh.dim());
  for (Eigen::Index k = 0; k < steps; ++k) {
    apply_device(sim, device.at(sim.time()));
    sim.step();
    out.time.push_back(sim.time());
    out.force.row(k) = device_force(sim).transpose();
  }
  return out;
}

ForceTrace multirate_force(LiveSimulation& sim, const DeviceDrag& device, double duration, double haptic_dt) {
  const double dt = sim.settings().dynamics.dt;
  const auto ratio = std::llround(dt / haptic_dt);
  if (!(haptic_dt > 0.0) || ratio < 1 || std::abs(static_cast<double>(ratio) * haptic_dt - dt) > 1e-9 * dt)
    throw InvalidArgument("multirate: the deformation step " + std::to_string(dt) +
                          " s is not a whole multiple of the haptic step " + std::to_string(haptic_dt) + " s");
  const auto ticks = static_cast<Eigen::Index>(std::llround(duration / haptic_dt));
  ForceTrace out;
  out.force.resize(ticks, sim.model().mesh.dim());
  apply_device(sim, device.at(0.0));
  HapticModel model = sim.haptic_model();  // in use: the grab's until the first step has finished, then the last's
  sim.step();                              // step 0: runs during [0, dt]
  for (Eigen::Index j = 1; j <= ticks; ++j) {
    const double t = static_cast<double>(j) * haptic_dt;
    if (j % ratio == 0) {  // the step started at t - dt has finished: its model takes over, the next step starts
      model = sim.haptic_model();
      apply_device(sim, device.at(t));
      sim.step();  // runs during [t, t + dt] while the ticks render `model`
    }
    out.time.push_back(t);
    out.force.row(j - 1) = model.render(device.at(t)).transpose();
  }
  return out;
}

double relative_force_error(const ForceTrace& a, const ForceTrace& b) {
  double scale = 0.0, worst = 0.0;
  for (Eigen::Index i = 0; i < b.force.rows(); ++i) scale = std::max(scale, b.force.row(i).norm());
  size_t shared = 0, ia = 0;
  for (size_t ib = 0; ib < b.time.size(); ++ib) {
    while (ia < a.time.size() && a.time[ia] < b.time[ib] - 1e-9) ++ia;
    if (ia == a.time.size()) break;
    if (std::abs(a.time[ia] - b.time[ib]) > 1e-9) continue;
    worst = std::max(worst,
                     (a.force.row(static_cast<Eigen::Index>(ia)) - b.force.row(static_cast<Eigen::Index>(ib))).norm());
    ++shared;
  }
  if (shared == 0) throw InvalidArgument("relative_force_error: the traces share no time");
  return scale > 0.0 ? worst / scale : worst;
}

}  // namespace hooke::interactive
