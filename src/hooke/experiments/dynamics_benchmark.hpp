#pragma once
/// The dynamics benchmark behind `hooke bench` (bench/bench_dynamics.cpp measures the same with Google
/// Benchmark, and adds Bullet): tetrahedral cylinders of about 1 000, 10 000 and 100 000 nodes (benchmark_cylinder,
/// r 1 cm, h 2 cm, E 14 630 Pa, 1 000 kg/m^3, bottom clamped), models of several methods at one nu, gravity and a
/// probe dragging the top's centre sideways; every row's error against a tightly converged implicit step.
#include <functional>
#include <hooke/calibrate/calibrated_model.hpp>
#include <hooke/contact/contact_block.hpp>
#include <hooke/core/types.hpp>
#include <hooke/model/problem.hpp>
#include <hooke/solve/simulator.hpp>
#include <string>
#include <vector>

namespace hooke::experiments {

/// The benchmark's cylinder of size 0, 1, 2: mesh::tet_cylinder(0.01, 0.02, n, layers) with (n, layers) = (12, 8),
/// (24, 24), (48, 57): 1 089, 11 425 and 103 066 nodes, minimum tet quality 0.29-0.34.
/// @throws InvalidArgument for another size
mesh::Mesh benchmark_cylinder(int size);

/// Its model: `method` (a calibration method's stable name) for E 14 630 Pa and `poisson`, lumped masses of
/// 1 000 kg/m^3. @throws InvalidArgument for an unknown method or a nu the method refuses
calibrate::CalibratedModel benchmark_model(int size, const std::string& method = "lloyd-tet", double poisson = 0.25);

/// The benchmark's probe: the top face's nodes within 0.35 r of the axis (held and dragged along x).
std::vector<int> benchmark_probe_nodes(const mesh::Mesh& cylinder);

struct DynamicsBenchmarkOptions {
  std::vector<int> sizes = {0, 1};  ///< 0, 1, 2: the 1 089-, 11 425- and 103 066-node cylinders
  /// calibration methods, one model each, default any-nu-tet, stiffness-fit-volume, lloyd-tet
  std::vector<std::string> methods = {"any-nu-tet", "stiffness-fit-volume", "lloyd-tet"};
  double poisson = 0.45;  ///< nu of every model, default 0.45 (soft tissue)
  int steps = 300;        ///< timed steps per integrator (after one untimed first step), default 300
  double dt = 1e-3;       ///< implicit step, s; explicit integrators run at 0.9 x their stability limit
  /// the probe's final offset along x, m, reached linearly at half the run's simulated time and held (0: no probe),
  /// default 2 mm (a tenth of the height)
  double drag = 2e-3;
  /// > 0: instead of the drag, the whole top face pressed down by this fraction of the height (its nodes held and
  /// moved along -z, reached linearly at half the run's simulated time, then held), e.g. 0.3; default 0
  double press = 0.0;
  /// > 0: instead, a rigid sphere of this radius (m) centred over the top, touching it, pressed into it by
  /// `tool_press` x the height (reached linearly at half the run's simulated time, then held), with the contact
  /// barrier of docs/contact.md on the boundary; default 0
  double tool_radius = 0.0;
  double tool_press = 0.1;
  /// the models' large-strain term law (calibrate::SpringModel::spring_exponent, volume_exponent), default Hookean
  double spring_exponent = 1.0;
  double volume_exponent = 1.0;
  /// rows to run by name (e.g. "quasi-newton", "local-global (chebyshev)"; empty = all)
  std::vector<std::string> integrators;
  /// Called with one line after each row, each model's calibration and each converged reference: what was
  /// measured and the seconds since the run began (`hooke bench` prints it on standard error); may be empty.
  std::function<void(const std::string&)> progress;
};

/// The benchmark's probe protocol: `nodes` held and dragged along x by `distance` m, linearly until `ramp_s` s of
/// simulated time (the runs use half their simulated time), then held; no probe when `nodes` is empty.
struct BenchmarkDrag {
  std::vector<int> nodes;
  double distance = 0.0;           ///< m
  double ramp_s = 1.0;             ///< s, > 0
  Vec3 direction = Vec3::UnitX();  ///< unit direction of the move: +x for the drag, -z for a press
  /// Or a rigid tool moved from `tool_start` (m) by the same offsets, against the model's contact block `contact`
  /// (whose tool it is); `nodes` is then empty.
  std::shared_ptr<contact::RigidTool> tool;
  const contact::ContactBlock* contact = nullptr;
  Vec3 tool_start = Vec3::Zero();
  /// The offset along `direction` at simulated time t (s), m.
  double offset(double t) const;
  /// Sets `sim`'s probe (or moves the tool: solve::move_tool) to the offset at the end of its next step of dt s
  /// (nothing without nodes or a tool).
  void before_step(solve::Simulator& sim, double dt) const;
};

/// The benchmark's accuracy reference: positions after 1 + `steps` implicit-Euler steps of `dt` s with Newton
/// converged to 1e-12, the probe following `probe` before each step. @throws solve errors (a step that does not
/// converge)
VecX converged_reference(const model::Problem& problem, const solve::Dynamics& dynamics, double dt, int steps,
                         const BenchmarkDrag& probe = {});

/// Largest node distance between `x` and `reference` (3D positions, m) relative to the reference's largest
/// displacement from `rest` (0 when the reference did not move): the benchmark's error measure.
double relative_error(const VecX& x, const VecX& reference, const VecX& rest);

/// Spring-force throughput on one mesh beside the in-run bandwidth bound.
struct SpringThroughput {
  int nodes = 0, springs = 0;
  double ns_per_spring = 0.0;       ///< median pass time / springs
  double bandwidth_fraction = 0.0;  ///< (24 B per spring + 72 B per node) / pass time / triad bandwidth
};

/// ms per step of one integrator on one mesh.
struct StepTiming {
  int nodes = 0;
  std::string method;  ///< the model's calibration method
  std::string integrator;
  double dt = 0.0;  ///< s
  double median_ms = 0.0, p95_ms = 0.0, p99_ms = 0.0;
  double iterations = 0.0;         ///< solver iterations per step
  double linear_iterations = 0.0;  ///< conjugate-gradient iterations per step (cg rows; 0 otherwise)
  int not_converged = 0;           ///< steps that ended above their tolerance within their budget (quasi-newton)
  /// Max node distance to implicit Euler converged tightly (Newton to 1e-12) after the same steps, relative to its
  /// largest displacement; -1 where the integrator solves another problem (explicit steps, quasi-static).
  double error_vs_converged = -1.0;
  /// with a tool: the force on it after the last step, N (along the press), and the converged reference's
  double tool_force = 0.0, reference_tool_force = 0.0;
};

struct DynamicsBenchmarkReport {
  double triad_gbps = 0.0;  ///< STREAM-like triad on all threads, GB/s, measured first
  std::vector<SpringThroughput> springs;
  std::vector<StepTiming> steps;
  std::vector<std::string> notes;  ///< what was skipped and why
};

/// Runs the benchmark: triad, spring forces (median of 30 passes), then every integrator per mesh and method
/// (implicit-euler and quasi-static only up to the 11 425-node mesh: their Newton matrices need a fresh
/// factorisation of 310 000 DOFs on the largest one; local-global only on spring models). Every timed run is
/// checked after each step (untimed): a run that leaves the admissible set (an inverted element, a non-finite
/// position) or ends a Newton step above its tolerance is not reported; a note says which and where. Budgeted
/// steps (quasi-newton) that end above their tolerance are counted in StepTiming::not_converged.
/// @throws InvalidArgument on a size outside 0..2, steps < 1, an unknown method or row name
DynamicsBenchmarkReport run_dynamics_benchmark(const DynamicsBenchmarkOptions& options);

/// The report as Markdown tables.
std::string dynamics_benchmark_markdown(const DynamicsBenchmarkReport& report);

}  // namespace hooke::experiments
