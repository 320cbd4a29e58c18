#pragma once
/// Dynamics of any model: masses, gravity, Rayleigh damping, and a time integrator (docs/architecture.md: one
/// simulation core for every model; integrators see only the model's energy, forces and Hessian).
#include <hooke/model/problem.hpp>
#include <hooke/solve/integrator.hpp>
#include <memory>

namespace hooke::solve {

/// What dynamics adds to a static problem.
struct Dynamics {
  VecX mass;                       ///< lumped mass per DOF, kg (size dof_count; > 0 on free DOFs)
  VecX gravity;                    ///< acceleration of gravity, m/s^2 (size dim; empty = none)
  double mass_damping = 0.0;       ///< Rayleigh alpha, 1/s: damping force -alpha M v
  double stiffness_damping = 0.0;  ///< Rayleigh beta, s: damping force -beta K0 v, K0 = the Hessian at rest
};

/// Newton's options of the implicit time steps (implicit-euler, implicit-euler-linearised, quasi-static): the
/// NewtonOptions defaults except 60 iterations per step, factorisation reuse across iterations and steps (modified
/// Newton) on, and no GMRES refinement (it allocates; the real-time loop must not).
inline NewtonOptions time_step_newton_options() {
  NewtonOptions o;
  o.max_iterations = 60;
  o.reuse_factorization = true;
  o.refine_approximate_steps = false;
  return o;
}

/// The quasi-newton integrator's budget and stopping test (docs/simulation.md says how they were chosen).
struct QuasiNewtonOptions {
  /// L-BFGS iterations per step at most: the real-time budget, default 8
  int max_iterations = 8;
  /// the step stops when |gradient| on the free DOFs <= tolerance x the step's force scale (|loads| + the first
  /// |gradient|, N), default 1e-2 (on the benchmark cylinders 3e-4-9e-4 of the largest displacement off a converged
  /// step after 300 steps, docs/simulation.md); in (0, 1)
  double tolerance = 1e-2;
  /// curvature pairs kept (Liu et al. 2017 use 5), carried across steps while dt and the fixed DOFs stay; >= 0,
  /// default 5
  int history = 5;
  QuasiNewtonHessian initial_hessian = QuasiNewtonHessian::kAuto;  ///< default auto (rest for exact Hessians)
  double isotropic_scale =
      2.0;  ///< isotropic: the factor on the blocks' traces / dim, default 2 (measured best of 1-3)
};

struct SimulatorOptions {
  /// default quasi-newton: every model, at a fixed budget per step, measured within 1e-3 of a converged step on
  /// the benchmark cylinders (docs/simulation.md)
  Integrator integrator = Integrator::kQuasiNewton;
  /// implicit-euler, implicit-euler-linearised, quasi-static: the Newton core's options (the linearised step uses
  /// linear_solver, backend, project_psd and cg_tolerance), default time_step_newton_options()
  NewtonOptions newton = time_step_newton_options();
  int local_global_iterations = 10;                 ///< local-global: iterations per step (Liu et al. use about 10)
  GlobalSolve global_solve = GlobalSolve::kDirect;  ///< local-global: the global step's linear solver
  /// local-global with chebyshev: false = plain Jacobi sweeps (for comparison; may be unstable for odd iteration
  /// counts, docs/simulation.md)
  bool chebyshev_acceleration = true;
  QuasiNewtonOptions quasi_newton;  ///< quasi-newton: budget and tolerance
};

/// A haptic or mouse probe: it grabs nodes and either drives them (as a stiff haptic device or a mouse drag
/// would) or pushes on them with a force.
struct Probe {
  std::vector<int> nodes;      ///< grabbed nodes (empty = no probe)
  bool drive_position = true;  ///< true: the nodes follow grab position + offset; false: `force` is applied
  VecX offset;                 ///< drive: displacement of the grabbed nodes from where they were grabbed, m (dim)
  VecX force;                  ///< push: total force, spread equally over the nodes, N (dim)
};

/// What one step did.
struct StepReport {
  int iterations = 0;             ///< Newton or local/global iterations (0 for explicit steps)
  int linear_iterations = 0;      ///< conjugate-gradient iterations over the step's Newton iterations (cg only)
  double residual = 0.0;          ///< |gradient of the step's objective| on the free DOFs at the end, N (0 explicit)
  bool converged = true;          ///< false when Newton ended above its tolerance (iteration limit, no descent)
  bool beyond_stable_dt = false;  ///< explicit only: dt exceeded stable_time_step()
  /// The force the body exerts on the probe at the end of the step, N (dim; zero without a probe): what a
  /// haptic device renders. Driven nodes: minus the force needed to hold them, sum over them of
  /// -(dE/dx - loads) (their own inertia excluded); pushed nodes: minus the applied force. Size dim, stored
  /// inline (no allocation).
  Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 3, 1> probe_force;
};

/// Steps a problem (model, fixed DOFs with their prescribed positions, dead external forces) in time.
/// Fixed DOFs follow problem.prescribed_positions (change them between steps to drive nodes); their velocity
/// is (new - old) / dt.
class Simulator {
 public:
  /// @throws InvalidArgument on mismatched sizes, a non-positive mass on a free DOF, negative damping, or
  ///   local-global with a model that has blocks other than springs (and the orientation guard)
  Simulator(model::Problem problem, Dynamics dynamics, SimulatorOptions options = {});
  ~Simulator();
  Simulator(Simulator&&) noexcept;
  Simulator& operator=(Simulator&&) noexcept;

  /// Advances the state by dt seconds. Allocates nothing after the first step (after the first step that follows
  /// a new dt or set_probe for local-global), except where implicit-euler / quasi-static with the Cholesky solver
  /// refactorise the Newton matrix inside CHOLMOD, or with Eigen's LDL^T below 1 000 DOFs (docs/simulation.md).
  /// @pre dt > 0
  StepReport step(double dt);

  double time() const;  ///< s
  /// Sets the simulated time, s (finite; a simulator rebuilt from another's state continues its clock).
  void set_time(double time);
  const VecX& positions() const;   ///< flat, m
  const VecX& velocities() const;  ///< flat, m/s
  void set_state(const VecX& positions, const VecX& velocities);

  /// The problem being simulated: change external_force or prescribed_positions between steps (not fixed_dofs:
  /// use set_probe to hold nodes during a run).
  model::Problem& problem();

  /// Grabs probe.nodes at their current positions (or updates offset / force of the current probe when the
  /// nodes are the same). An empty node list releases the probe.
  /// @throws InvalidArgument on a node out of range or an offset / force without dim components
  void set_probe(const Probe& probe);
  const Dynamics& dynamics() const;

  double kinetic_energy() const;  ///< 1/2 v^T M v, J
  /// Elastic energy minus the work of the dead loads and gravity from the rest state, J.
  double potential_energy() const;
  /// Linear momentum sum M v per axis, kg m/s (size dim).
  VecX momentum() const;
  /// Explicit stability limit (s): 2 / omega_max (sqrt(1 + zeta^2) - zeta), omega_max^2 the largest eigenvalue of
  /// M^-1 K0 on the free DOFs (power iteration), zeta = (alpha / omega_max + beta omega_max) / 2 the Rayleigh
  /// damping ratio there (2 / omega_max undamped).
  double stable_time_step() const;
  /// The Hessian of the model's energy at its rest positions, N/m (dof_count square, both triangles, no fixed DOFs
  /// applied): assembled at the first call and kept (the integrators and the damping share it).
  const SparseMatrix& rest_stiffness();

 private:
  struct Impl;
  std::unique_ptr<Impl> m;
};

}  // namespace hooke::solve
