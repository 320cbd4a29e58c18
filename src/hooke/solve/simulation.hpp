#pragma once
/// A scripted dynamics run of any calibrated model (what `hooke simulate` does): bottom clamped (spring and FEM
/// models) or held by its anchors (surface model), gravity, Rayleigh damping, a probe ramped over the run, frames
/// handed to a sink, and a timing and energy summary.
#include <array>
#include <functional>
#include <hooke/calibrate/calibrated_model.hpp>
#include <hooke/contact/tool_path.hpp>
#include <hooke/solve/dynamics_setup.hpp>
#include <hooke/solve/simulator.hpp>
#include <memory>
#include <vector>

namespace hooke::solve {

struct SimulationOptions {
  SimulatorOptions simulator;  ///< integrator and its settings
  DynamicsSetup dynamics;      ///< dt, gravity, Rayleigh damping, Eq. 4's radius
  int steps = 100;             ///< number of steps (>= 1)
  int every = 0;               ///< a frame every this many steps; 0: about 100 frames
  bool clamp_bottom = true;    ///< clamp the nodes of the lowest face (not for a surface model)
  bool reorder = true;         ///< simulate in reverse Cuthill-McKee order (same trajectory, faster)
  int probe_node = -1;         ///< node grabbed by the probe, in the model's numbering (-1: none)
  VecX probe_offset;           ///< drive the probe node by this offset, m (dim), ramped linearly
  VecX probe_force;            ///< or push it with this force, N (dim), ramped linearly
  /// Keep going when a step ends above the Newton tolerance (counted in SimulationSummary::not_converged) instead
  /// of failing with SolverFailure at that step.
  bool allow_unconverged = false;
  /// A rigid tool pressing the body (docs/contact.md): its shape, moved along `tool_path` (pose at each step's end
  /// time), against the body's boundary with the contact barrier of activation distance `contact_distance` (m; 0:
  /// 1 % of the mean boundary edge). None by default. Shared: simulate sets its pose.
  std::shared_ptr<contact::RigidTool> tool;
  contact::ToolPath tool_path;
  double contact_distance = 0.0;
  /// Static rigid obstacles the body may rest on (half-spaces: contact::parse_obstacle), each with its own contact
  /// block on the boundary, frictionless; the body must start outside them.
  std::vector<contact::RigidTool> obstacles;
  /// Coulomb friction coefficient of the tool's and the obstacles' contacts (>= 0; 0: frictionless), and the creep
  /// velocity eps_v below which friction acts as a stiff viscous drag (m/s, > 0; 0: contact::default_creep_velocity of
  /// the body's bounding-box diagonal per second): a contact below the friction limit slips slower than eps_v
  /// (docs/contact.md).
  double friction = 0.0;
  double creep_velocity = 0.0;
};

struct SimulationSummary {
  std::vector<double> step_ms;    ///< wall time of each step, ms
  long iterations = 0;            ///< Newton / local-global iterations over the run
  int not_converged = 0;          ///< steps that ended above the Newton tolerance (only with allow_unconverged)
  int beyond_stable_dt = 0;       ///< explicit steps beyond the stability limit
  double stable_time_step = 0.0;  ///< explicit stability limit, s
  double energy_start = 0.0;      ///< kinetic + potential at t = 0, J
  double energy_end = 0.0;        ///< at the end, J
  double kinetic_end = 0.0;       ///< J
  double max_probe_force = 0.0;   ///< largest |force on the device| over the run, N
  double time = 0.0;              ///< simulated time, s
  /// With a tool, per step: the step's end time (s) and the force the body exerts on the tool there (N, x y z).
  std::vector<std::array<double, 4>> tool_force;
  double smallest_gap = 0.0;      ///< with a tool: the smallest node-to-tool distance after any step, m (> 0)
  int pushed_nodes = 0;           ///< nodes moved out of the tool's way before a step (the tool outran their gap)
  double contact_distance = 0.0;  ///< the activation distance used, m
  double creep_velocity = 0.0;    ///< with friction: eps_v used, m/s
  /// per obstacle: the force the body exerts on it at the end, N (x y z), and the smallest gap over the run, m
  std::vector<std::array<double, 3>> obstacle_force;
  std::vector<double> obstacle_gap;
};

/// Receives a frame: step number, time (s), displacement and velocity (flat, in the model's node order).
using FrameSink = std::function<void(int step, double time, const VecX& displacement, const VecX& velocity)>;

/// Runs `model` for options.steps steps, calling `frames` at step 0, every options.every steps and at the end.
/// @throws InvalidArgument for options out of range (dt <= 0, steps < 1, a probe without exactly one of offset
///   and force of dim components, a probe node out of range); SolverFailure when a step inverts an element or
///   produces non-finite positions
SimulationSummary simulate(const calibrate::CalibratedModel& model, const SimulationOptions& options,
                           const FrameSink& frames);

}  // namespace hooke::solve
