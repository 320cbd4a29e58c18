#pragma once
/// Static equilibrium of a Problem: the linear solve K u = f, and Newton's method on the total potential
/// energy with line search, load stepping and a stability check of every accepted state.
#include <hooke/core/sparse_cholesky.hpp>
#include <hooke/model/problem.hpp>
#include <hooke/solve/newton.hpp>
#include <string>
#include <vector>

namespace hooke::solve {

enum class SolveStatus {
  kConverged,     ///< a stable equilibrium at the full load
  kNotConverged,  ///< Newton failed even with the smallest load step; the state is the last converged one
  kUnstable,      ///< stability was lost at `critical_load_factor`; the state is the last stable one
  kSingular       ///< the stiffness on the free DOFs is singular (the body is not held)
};

/// Stable name: "converged", "not-converged", "unstable", "singular".
std::string_view status_name(SolveStatus status);

/// What a static solve did. Numbers, never exceptions: see require_converged().
struct SolveReport {
  SolveStatus status = SolveStatus::kNotConverged;
  int iterations = 0;                    ///< Newton iterations over all load steps (1 for the linear solve)
  int load_steps = 0;                    ///< accepted load steps
  double load_factor = 0.0;              ///< load factor of the returned state (1 = the full load)
  double residual = 0.0;                 ///< norm of the free-DOF force residual at the returned state, N
  double reference_force = 0.0;          ///< norm of the applied forces, N (the residual's scale)
  double min_eigenvalue = 0.0;           ///< smallest tangent eigenvalue on the free DOFs at the returned state, N/m
  double critical_load_factor = -1.0;    ///< load factor where stability is lost, or -1
  int free_dofs = 0;                     ///< number of unknowns
  double assembly_seconds = 0.0;         ///< time in Hessian and force assembly
  double factorization_seconds = 0.0;    ///< time in sparse factorisations
  int factorizations = 0;                ///< sparse factorisations (Newton's and the stability tests')
  double solve_seconds = 0.0;            ///< total wall time
  std::string backend;                   ///< linear solver used ("cholmod", "eigen-ldlt")
  std::vector<double> residual_history;  ///< residual norm at each Newton iteration, N
  std::string message;                   ///< one sentence on the outcome
};

/// Throws SolverFailure with report.message unless report.status is kConverged.
void require_converged(const SolveReport& report);

/// Result of a static solve: node positions (flat, m) and the report.
struct StaticResult {
  VecX positions;
  SolveReport report;
};

struct LinearOptions {
  CholeskyBackend backend = CholeskyBackend::kAuto;  ///< sparse factorisation
  bool estimate_min_eigenvalue = false;              ///< also fill report.min_eigenvalue (costs a few solves)
};

/// Linear static solve: K u = f on the free DOFs with K the model's Hessian at rest (the FEM stiffness for
/// the linear law; the linearised model otherwise) and u the displacement of the prescribed DOFs applied.
StaticResult linear_static(const model::Problem& problem, const LinearOptions& options = {});

/// linear_static under each of several loads (flat, N, size dof_count, each as problem.external_force would be) on
/// the same problem: one assembly and one factorisation for all (their times are in the first report).
std::vector<StaticResult> linear_statics(const model::Problem& problem, const std::vector<VecX>& loads,
                                         const LinearOptions& options = {});

/// Options of the nonlinear static solve: Newton's (the same core as the implicit time steps) and the load
/// stepping around it.
struct StaticOptions {
  /// Newton per load step (defaults of NewtonOptions: tolerance 1e-9, 40 iterations, Cholesky, no reuse)
  NewtonOptions newton;
  int initial_load_steps = 4;   ///< the load is applied in this many equal steps at first, default 4
  double min_load_step = 1e-3;  ///< give up when a step below this fails, default 1e-3
  bool check_stability = true;  ///< test positive definiteness after every accepted step, default true
  /// With check_stability: also estimate report.min_eigenvalue at a converged state, default true. The estimate is
  /// a bisection over shifted factorisations (about 20 of them): minutes on a 200 000-DOF model, where stability
  /// itself costs one factorisation per accepted step. A solve that fails always estimates it (its message gives it).
  bool estimate_min_eigenvalue = true;
  int bisection_steps = 7;  ///< refinements of the critical load factor, default 7
  /// Prescribed displacements (problem.prescribed_positions - rest on the fixed DOFs) follow the load factor as the
  /// forces do: each load step moves the held DOFs to rest + lambda u_c and the free ones by the tangent's response
  /// to that move (a linear predictor), so that a press or pull of tens of per cent is reached in admissible steps.
  /// Default false: the prescribed positions hold from the start.
  bool ramp_prescribed = false;
  /// Optional initial guess at the full load (flat positions, m, size dof_count; prescribed DOFs are taken
  /// from the problem): Newton is tried from it first, and load stepping from rest only if that fails. Empty
  /// (default): load stepping from rest.
  VecX start;
};

/// Newton's method (NewtonSolver) on Pi(x) = E(x) - lambda f.(x - X), load stepping lambda: 0 -> 1 with step halving on
/// failure, and Levenberg shifts where the tangent is indefinite. Every accepted state is checked for stability (the
/// tangent on the free DOFs must be positive definite); when stability is lost, the critical load factor is bracketed
/// by bisection and the last stable state is returned with status kUnstable: an unstable equilibrium is never the
/// answer. A model with non-conservative blocks (Model::conservative() false) has no potential: its line search
/// backtracks on the residual norm instead, with the blocks' symmetric Jacobian approximations. Where a block's
/// Hessian is approximate (Model::exact_hessian() false) Newton steps are refined by GMRES and stability is
/// not checked (the message says so).
StaticResult static_equilibrium(const model::Problem& problem, const StaticOptions& options = {});

/// static_equilibrium under each of several loads (flat, N, size dof_count, each as problem.external_force would be)
/// on the same problem, one after the other: the start state's stability is tested once for all (the supports and
/// the start are the same), and one Newton solver serves them all, so that with options.newton.reuse_factorization
/// the factorisation kept from one load starts the next (modified Newton). The results are those of separate
/// static_equilibrium calls to Newton's tolerance. @throws InvalidArgument with options.start and several loads
std::vector<StaticResult> static_equilibria(const model::Problem& problem, const std::vector<VecX>& loads,
                                            const StaticOptions& options = {});

}  // namespace hooke::solve
