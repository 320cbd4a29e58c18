#pragma once
/// Newton's method with line search: the one nonlinear core under the static solver (static_equilibrium) and the
/// implicit time steps (implicit-euler, implicit-euler-linearised, quasi-static). Exact Hessian with a
/// PSD-projected fallback and Levenberg shifts; sparse Cholesky (with modified-Newton reuse) or block-Jacobi
/// conjugate gradients (Eisenstat-Walker forcing); Armijo backtracking on the objective, or on the residual norm
/// where the forces have no potential; GMRES refinement of the step where the Hessian is an approximation.
#include <hooke/core/sparse_cholesky.hpp>
#include <hooke/core/types.hpp>
#include <memory>
#include <string_view>
#include <vector>

namespace hooke::solve {

/// Linear solver of the Newton steps.
enum class NewtonLinearSolver {
  kCholesky,          ///< "cholesky": sparse Cholesky (CHOLMOD or Eigen), symbolic analysis reused across calls
  kConjugateGradient  ///< "cg": node-block-Jacobi-preconditioned conjugate gradients, warm-started
};

NewtonLinearSolver newton_linear_solver_from_name(std::string_view name);  ///< @throws InvalidArgument
std::string_view newton_linear_solver_name(NewtonLinearSolver solver);     ///< "cholesky" or "cg"

/// Options of Newton's method, the same struct for statics and time steps (their defaults differ only where the
/// caller sets them: StaticOptions::newton and SimulatorOptions::newton document theirs).
struct NewtonOptions {
  /// converged when |gradient| on the free DOFs <= tolerance x the objective's force scale (N), default 1e-9
  double tolerance = 1e-9;
  /// also converged when a Newton step moves no DOF by more than this times the body's size (the force test alone
  /// drowns in round-off at tiny loads), default 1e-13
  double step_tolerance = 1e-13;
  int max_iterations = 40;  ///< Newton iterations per solve (per load step in statics), default 40
  /// true: every element Hessian projected to PSD (robust, linear convergence); false (default): the exact
  /// Hessian (quadratic convergence), the projected one only where the exact matrix is not positive definite
  bool project_psd = false;
  NewtonLinearSolver linear_solver = NewtonLinearSolver::kCholesky;  ///< default cholesky
  CholeskyBackend backend = CholeskyBackend::kAuto;                  ///< cholesky: the factorisation, default auto
  /// cg: the relative residual the conjugate gradients reach near the solution (inexact Newton: looser far from
  /// it), default 1e-6
  double cg_tolerance = 1e-6;
  /// cholesky: keep the last factorisation (modified Newton, possibly from an earlier solve) while it reduces the
  /// residual fourfold per iteration, refactorise otherwise; default false
  bool reuse_factorization = false;
  /// cholesky with reuse_factorization and an exact Hessian: where the kept factorisation alone no longer reduces
  /// the residual fourfold, first solve the current Newton system by conjugate gradients preconditioned with the
  /// kept factor (inexact Newton, the forcing term as for cg), with at most this many iterations, and refactorise
  /// only when they do not reach it or meet non-positive curvature. A local change of the tangent (a few stiffening
  /// elements) is a low-rank change of the factorised matrix, which such CG resolves in a few solves, each about
  /// 1/25 of a factorisation on a 200 000-DOF tet model (on a float copy of the factor, which a positive value
  /// keeps beside it: 1.5x the factor's memory, 0.6x its solve time). 0 (default): refactorise at once
  int reuse_krylov_iterations = 0;
  /// where the objective's Hessian is approximate: refine each step by GMRES on forward differences of the
  /// gradient (cholesky only; allocates), default true
  bool refine_approximate_steps = true;
};

/// True when `step` moves no DOF by more than `options.step_tolerance` x `size` (m, the body's size): round-off,
/// nothing more to gain (Newton's and quasi-Newton's shared stopping test).
inline bool is_round_off_step(const Eigen::Ref<const VecX>& step, const NewtonOptions& options, double size) {
  return step.cwiseAbs().maxCoeff() <= options.step_tolerance * size;
}

/// What one Newton solve did.
struct NewtonReport {
  int iterations = 0;          ///< Newton iterations
  long linear_iterations = 0;  ///< conjugate-gradient iterations (cg, or preconditioned by a kept factor)
  double residual = 0.0;       ///< |gradient| on the free DOFs at the end, N
  bool converged = false;      ///< residual (or step) test met
};

/// The function whose stationary point Newton's method finds, over all DOFs of a model with some DOFs held.
/// Vectors are flat (size dof_count); fixed DOFs never move and their gradient entries are zero.
class NewtonObjective {
 public:
  virtual ~NewtonObjective() = default;
  /// False when the forces have no potential: value() is not used and the line search backtracks on |gradient|.
  virtual bool conservative() const = 0;
  /// False when newton_matrix() is only an approximation of the gradient's derivative.
  virtual bool exact_hessian() const = 0;
  /// Per DOF: 1 where the DOF is held.
  virtual const std::vector<char>& fixed() const = 0;
  virtual int dim() const = 0;      ///< DOFs per node (2 or 3)
  virtual double size() const = 0;  ///< the body's extent, m (the step test)
  /// The objective at z, J (+infinity where z is inadmissible, e.g. an inverted element).
  virtual double value(const VecX& z) = 0;
  /// Its gradient at z into `out` (size of z; zero on fixed DOFs), N. Allocates nothing.
  virtual void gradient(const VecX& z, VecX& out) = 0;
  /// The force scale of the convergence test, N, at the z of the last gradient() call.
  virtual double force_scale() const = 0;
  /// The Newton matrix at z (N/m), rows and columns of fixed DOFs those of the identity; with `project`, every
  /// element Hessian is projected to PSD first. Its pattern never changes; the reference is valid until the
  /// next call.
  virtual SparseMatrix& newton_matrix(const VecX& z, bool project) = 0;
  /// Index into newton_matrix().valuePtr() of each DOF's diagonal entry.
  virtual const std::vector<int>& diagonal() const = 0;
};

/// Newton's method with its factorisation and work vectors kept between solves (for 1 kHz loops).
class NewtonSolver {
 public:
  explicit NewtonSolver(const NewtonOptions& options = {});
  ~NewtonSolver();
  NewtonSolver(NewtonSolver&&) noexcept;
  NewtonSolver& operator=(NewtonSolver&&) noexcept;

  /// Drives the gradient of `f` to zero from z (flat positions, m; updated in place): Newton directions, Armijo
  /// backtracking (sufficient decrease 1e-4, up to 40 halvings; on a smaller residual where the energy difference
  /// is round-off), steepest descent where a direction is no descent. Allocates nothing after the first call with
  /// the same objective (except CHOLMOD refactorisations, GMRES refinement and `residual_history`).
  /// @param residual_history  if not null, |gradient| of every iteration is appended (N)
  NewtonReport solve(NewtonObjective& f, VecX& z, std::vector<double>* residual_history = nullptr);

  /// One Newton direction at z for the given gradient (no line search), into `delta`: (projected where the exact
  /// matrix is not positive definite, shifted where even that fails) H delta = -gradient, cg to relative residual
  /// `cg_tolerance`. @return false when no positive-definite shift of the matrix was found
  bool direction(NewtonObjective& f, const VecX& z, const VecX& gradient, double cg_tolerance, VecX& delta);

  /// Factorises the exact Newton matrix at z and keeps the factorisation, as the first step of the next solve()
  /// would (with reuse_factorization, that solve then starts from it). Cholesky only.
  /// @return false when the matrix is not positive definite (nothing is kept then)
  bool factorize_at(NewtonObjective& f, const VecX& z);

  /// Drops the kept factorisation and preconditioner: call when the objective's matrix changes in kind (a new time
  /// step, other fixed DOFs, another objective).
  void invalidate();
  const NewtonOptions& options() const;
  /// Conjugate-gradient iterations of the last solve() or direction() (with cholesky: those preconditioned by the
  /// kept factor, reuse_krylov_iterations).
  long linear_iterations() const;
  /// Time spent in sparse factorisations since construction, s.
  double factorization_seconds() const;
  /// Sparse factorisations (successful or not) since construction.
  int factorizations() const;
  /// "cholmod", "eigen-ldlt" or "cg".
  std::string_view backend_name() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m;
};

}  // namespace hooke::solve
