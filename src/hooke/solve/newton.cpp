#include <Eigen/QR>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/core/name_table.hpp>
#include <hooke/solve/detail/sparse_ops.hpp>
#include <hooke/solve/newton.hpp>
#include <limits>
#include <string>

namespace hooke::solve {
namespace {

using Clock = std::chrono::steady_clock;

constexpr NameTable<NewtonLinearSolver, 2> kLinearSolvers{
    "linear solver", {{{NewtonLinearSolver::kCholesky, "cholesky"}, {NewtonLinearSolver::kConjugateGradient, "cg"}}}};

}  // namespace

NewtonLinearSolver newton_linear_solver_from_name(std::string_view name) { return kLinearSolvers.from_name(name); }
std::string_view newton_linear_solver_name(NewtonLinearSolver solver) { return kLinearSolvers.name(solver); }

struct NewtonSolver::Impl {
  NewtonOptions opt;
  SparseCholesky cholesky;
  bool have_factor = false;  // `cholesky` holds a factorisation of an earlier Newton matrix of this objective
  double factor_seconds = 0.0;
  int factor_count = 0;
  VecX grad, delta, trial, grad_trial;
  VecX cg_r, cg_z, cg_p, cg_q, cg_blocks;
  long cg_iterations = 0;             // during the current solve or direction
  std::vector<int> cg_block_offsets;  // per DOF and block column: offset in the Newton matrix's values, or -1
  Eigen::Index cg_pattern_nonzeros = -1;
  bool cg_blocked3 = false;  // the Newton matrix is made of whole 3 x 3 node blocks (detail::node_blocked)

  // The kept-factor CG's preconditioner solves read a float copy of the factor (the bunny's model: 0.114 -> 0.070
  // s per solve, 240 of them in a certificate); Newton's own steps stay in double precision.
  explicit Impl(const NewtonOptions& o) : opt(o), cholesky(o.backend) {
    if (kept_factor_cg()) cholesky.set_solve_precision(SolvePrecision::kSingle);
  }

  bool kept_factor_cg() const { return !cg() && opt.reuse_factorization && opt.reuse_krylov_iterations > 0; }

  bool cg() const { return opt.linear_solver == NewtonLinearSolver::kConjugateGradient; }

  bool factorize(const SparseMatrix& h) {
    const auto t0 = Clock::now();
    const bool ok = cholesky.factorize(h);
    ++factor_count;
    factor_seconds += std::chrono::duration<double>(Clock::now() - t0).count();
    return ok;
  }

  // Factorises h, with Levenberg shifts on the free diagonal where the (projected) matrix is still not positive
  // definite (free particles in a quasi-static step, a buckling body, round-off).
  bool factorize_shifted(NewtonObjective& f, SparseMatrix& h) {
    double shift = 0.0;
    const double diag = h.diagonal().cwiseAbs().maxCoeff();
    const std::vector<int>& d = f.diagonal();
    const std::vector<char>& fixed = f.fixed();
    for (int attempt = 0; attempt < 30; ++attempt) {
      if (factorize(h)) return true;
      const double next = shift == 0.0 ? 1e-10 * diag : 10.0 * shift;
      for (size_t i = 0; i < fixed.size(); ++i)
        if (!fixed[i]) h.valuePtr()[d[i]] += next - shift;
      shift = next;
    }
    return false;
  }

  // Node-block Jacobi preconditioner: the inverse of each node's dim x dim diagonal block of h (identity rows for
  // fixed DOFs). Elasticity couples a node's axes strongly, so this takes about half the CG iterations of the
  // scalar diagonal on the spring cylinders. cg_blocks holds the inverses, dim^2 per node, row-major.
  void block_preconditioner(const SparseMatrix& h, int d) {
    const Eigen::Index nd = h.rows(), n = nd / d;
    if (cg_pattern_nonzeros != h.nonZeros()) {  // where each block entry sits in h's values (the pattern is fixed)
      cg_pattern_nonzeros = h.nonZeros();
      cg_blocked3 = d == 3 && detail::node_blocked(h, 3);
      cg_block_offsets.assign(static_cast<size_t>(nd * d), -1);
      for (Eigen::Index c = 0; c < nd; ++c)
        for (SparseMatrix::InnerIterator it(h, c); it; ++it)
          if (it.row() / d == c / d)
            cg_block_offsets[static_cast<size_t>(d * c + it.row() % d)] =
                static_cast<int>(&it.valueRef() - h.valuePtr());
      cg_blocks.setZero(nd * d);
    }
    const double* values = h.valuePtr();
    for (Eigen::Index i = 0; i < n; ++i) {
      Eigen::Matrix3d b = Eigen::Matrix3d::Identity();
      for (int a = 0; a < d; ++a)
        for (int c = 0; c < d; ++c) {
          const int q = cg_block_offsets[static_cast<size_t>(d * (d * i + c) + a)];
          b(a, c) = q >= 0 ? values[q] : 0.0;
        }
      const Eigen::Matrix3d inverse = b.inverse();
      for (int a = 0; a < d; ++a)
        for (int c = 0; c < d; ++c) cg_blocks(d * d * i + d * a + c) = inverse(a, c);
    }
  }

  void product(const SparseMatrix& h, const VecX& z, VecX& out) const {
    if (cg_blocked3)
      detail::multiply_blocked3(h, z, out);
    else
      detail::multiply(h, z, out);
  }

  void precondition(const VecX& r, VecX& z, int d) const {
    for (Eigen::Index i = 0; i < r.size() / d; ++i)
      for (int a = 0; a < d; ++a) {
        double sum = 0.0;
        for (int c = 0; c < d; ++c) sum += cg_blocks(d * d * i + d * a + c) * r(d * i + c);
        z(d * i + a) = sum;
      }
  }

  // Preconditioned conjugate gradients on h x = -g to |residual| <= tolerance |g|, warm-started from x. Returns
  // false where h shows a direction of non-positive curvature (not positive definite).
  bool conjugate_gradient(const SparseMatrix& h, int d, const VecX& g, double tolerance, VecX& x) {
    const Eigen::Index nd = g.size();
    if (cg_r.size() != nd) {
      for (VecX* w : {&cg_r, &cg_z, &cg_p, &cg_q}) w->setZero(nd);
      x.setZero(nd);
    }
    block_preconditioner(h, d);
    product(h, x, cg_q);
    cg_r = -g - cg_q;
    const double target = tolerance * g.norm();
    precondition(cg_r, cg_z, d);
    cg_p = cg_z;
    double rz = cg_r.dot(cg_z);
    for (Eigen::Index k = 0; k < 4 * nd && cg_r.norm() > target; ++k) {
      ++cg_iterations;
      product(h, cg_p, cg_q);
      const double curvature = cg_p.dot(cg_q);
      if (!(curvature > 0.0)) return false;
      const double alpha = rz / curvature;
      x += alpha * cg_p;
      cg_r -= alpha * cg_q;
      precondition(cg_r, cg_z, d);
      const double rz_next = cg_r.dot(cg_z);
      cg_p = cg_z + (rz_next / rz) * cg_p;
      rz = rz_next;
    }
    return true;
  }

  // Conjugate gradients on h x = -g preconditioned by the kept factorisation (of an earlier Newton matrix), from
  // x = 0, to |residual| <= tolerance |g| within `limit` iterations. Returns false where they do not reach it or h
  // shows a direction of non-positive curvature. Every iterate from 0 is a descent direction for a definite h. The
  // preconditioner is the factor's float copy: L~ L~^T, still symmetric positive definite (SolvePrecision).
  bool factor_preconditioned_cg(const SparseMatrix& h, const VecX& g, double tolerance, int limit, VecX& x) {
    const Eigen::Index nd = g.size();
    for (VecX* w : {&cg_r, &cg_z, &cg_p, &cg_q})
      if (w->size() != nd) w->setZero(nd);
    x.setZero(nd);
    cg_r = -g;
    const double target = tolerance * g.norm();
    cg_z = cg_r;
    cholesky.solve_in_place(cg_z.data(), 1);
    cg_p = cg_z;
    double rz = cg_r.dot(cg_z);
    for (int k = 0; k < limit; ++k) {
      ++cg_iterations;
      detail::multiply(h, cg_p, cg_q);
      const double curvature = cg_p.dot(cg_q);
      if (!(curvature > 0.0)) return false;
      const double alpha = rz / curvature;
      x += alpha * cg_p;
      cg_r -= alpha * cg_q;
      if (cg_r.norm() <= target) return true;
      cg_z = cg_r;
      cholesky.solve_in_place(cg_z.data(), 1);
      const double rz_next = cg_r.dot(cg_z);
      cg_p = cg_z + (rz_next / rz) * cg_p;
      rz = rz_next;
    }
    return false;
  }

  bool direction(NewtonObjective& f, const VecX& z, const VecX& g, double cg_tolerance, VecX& out) {
    if (cg()) {
      if (out.size() != g.size()) out.setZero(g.size());
      if (conjugate_gradient(f.newton_matrix(z, opt.project_psd), f.dim(), g, cg_tolerance, out) || opt.project_psd)
        return true;
      out.setZero();
      return conjugate_gradient(f.newton_matrix(z, true), f.dim(), g, cg_tolerance, out);
    }
    if (opt.project_psd || !factorize(f.newton_matrix(z, false)))
      if (!factorize_shifted(f, f.newton_matrix(z, true))) return false;
    out = -g;
    cholesky.solve_exact_in_place(out.data(), 1);
    return true;
  }

  // Where the Newton matrix S only approximates the gradient's Jacobian J (the symmetric part of non-conservative
  // blocks' Jacobians, a dense coupling dropped): solve J d = -g by GMRES (Saad, Iterative Methods, Alg. 6.9) right-
  // preconditioned with S^-1 (the current factor), J v from a forward difference of the gradient (one gradient
  // evaluation per iteration), to |g + J d| <= 1e-6 |g| or 40 iterations; keeps the plain S^-1 step when better.
  void refine(NewtonObjective& f, const VecX& z, const VecX& g, VecX& d) {
    const double beta = g.norm();
    if (!(beta > 0.0)) return;
    auto jacobian_times = [&](const VecX& v) {
      const double vmax = v.cwiseAbs().maxCoeff();
      if (!(vmax > 0.0)) return VecX(VecX::Zero(v.size()));
      const double eps = 1e-7 * f.size() / vmax;
      VecX t = z + eps * v, gt(z.size());
      f.gradient(t, gt);
      return VecX((gt - g) / eps);
    };
    const Eigen::Index n = g.size();
    const int m = static_cast<int>(std::min<Eigen::Index>(40, n));
    Eigen::MatrixXd basis(n, m + 1), hess = Eigen::MatrixXd::Zero(m + 1, m);
    basis.col(0) = -g / beta;
    Eigen::VectorXd best;
    for (int k = 0; k < m; ++k) {
      VecX w = jacobian_times(cholesky.solve(basis.col(k)));
      for (int i = 0; i <= k; ++i) {
        hess(i, k) = basis.col(i).dot(w);
        w -= hess(i, k) * basis.col(i);
      }
      hess(k + 1, k) = w.norm();
      Eigen::VectorXd rhs = Eigen::VectorXd::Zero(k + 2);
      rhs(0) = beta;
      const Eigen::MatrixXd h = hess.topLeftCorner(k + 2, k + 1);
      best = h.colPivHouseholderQr().solve(rhs);
      const double defect = (h * best - rhs).norm();
      if (!(hess(k + 1, k) > 1e-14 * beta) || defect <= 1e-6 * beta) break;
      basis.col(k + 1) = w / hess(k + 1, k);
    }
    if (best.size() == 0 || !best.allFinite()) return;
    const VecX candidate = cholesky.solve(VecX(basis.leftCols(best.size()) * best));
    if ((g + jacobian_times(candidate)).norm() < (g + jacobian_times(d)).norm()) d = candidate;
    f.gradient(z, grad);  // jacobian_times left the objective's force scale at a trial point
  }

  // Per solve: the residual the kept factorisation last gave (modified Newton), the CG forcing term and the
  // residual it was chosen at, and the objective at the iterate.
  double previous = 0.0, eta = 0.1, last_residual = 0.0, phi = 0.0;

  // Inexact Newton's CG tolerance eta (Eisenstat & Walker 1996, choice 2) at iteration `it` with this residual:
  // it follows the residual's decrease, loose far from the solution (0.1, also at it = 0), down to cg_tolerance
  // near it.
  void update_forcing_term(int it, double residual) {
    if (it > 0 && last_residual > 0.0)
      eta = std::clamp(0.9 * (residual / last_residual) * (residual / last_residual), opt.cg_tolerance, 0.1);
    last_residual = residual;
  }

  // Set by step_direction: the last direction came from CG preconditioned by the kept factorisation.
  bool preconditioned = false;

  // The direction of iteration `it` at y into `delta`; false when none could be computed. `reuse`: from the kept
  // factorisation (modified Newton) instead of a new one.
  bool step_direction(NewtonObjective& f, const VecX& y, int it, double residual, bool reuse) {
    preconditioned = false;
    if (cg()) {
      update_forcing_term(it, residual);  // tightened below when the step is no descent
      if (!direction(f, y, grad, eta, delta)) return false;
      return grad.dot(delta) < 0.0 || eta <= opt.cg_tolerance || direction(f, y, grad, opt.cg_tolerance, delta);
    }
    if (reuse) {
      delta = -grad;
      cholesky.solve_exact_in_place(delta.data(), 1);
      return true;
    }
    if (have_factor && kept_factor_cg() && f.exact_hessian()) {
      // Inexact Newton on the current matrix with the kept factor as preconditioner.
      update_forcing_term(it, residual);
      if (factor_preconditioned_cg(f.newton_matrix(y, false), grad, eta, opt.reuse_krylov_iterations, delta)) {
        preconditioned = true;
        return true;
      }
    }
    if (!direction(f, y, grad, 0.0, delta)) return false;
    have_factor = true;
    if (!f.exact_hessian() && opt.refine_approximate_steps) refine(f, y, grad, delta);
    return true;
  }

  // Backtracking from y along delta into `trial`: Armijo on the objective (sufficient decrease 1e-4, 40 halvings),
  // a smaller residual where the energy difference is round-off, or (no potential) a residual decrease.
  bool line_search(NewtonObjective& f, const VecX& y, double slope, double residual) {
    double alpha = 1.0;
    for (int ls = 0; ls < 40; ++ls, alpha *= 0.5) {
      trial = y + alpha * delta;
      if (!f.conservative()) {
        f.gradient(trial, grad_trial);
        const double rt = grad_trial.norm();
        if (std::isfinite(rt) && rt <= (1.0 - 1e-4 * alpha) * residual) return true;
        continue;
      }
      const double p = f.value(trial);
      if (!std::isfinite(p)) continue;
      bool accept = p <= phi + 1e-4 * alpha * slope;
      if (!accept && std::abs(p - phi) <= 1e-12 * std::abs(phi)) {
        f.gradient(trial, grad_trial);
        accept = grad_trial.norm() < residual;
      }
      if (accept) {
        phi = p;
        return true;
      }
    }
    return false;
  }

  NewtonReport solve(NewtonObjective& f, VecX& y, std::vector<double>* history) {
    NewtonReport r;
    const Eigen::Index nd = y.size();
    for (VecX* w : {&grad, &trial, &grad_trial})
      if (w->size() != nd) w->setZero(nd);
    if (delta.size() != nd) delta.setZero(nd);
    cg_iterations = 0;
    phi = f.conservative() ? f.value(y) : 0.0;
    previous = std::numeric_limits<double>::infinity();
    eta = 0.1;
    int it = 0;
    for (; it < opt.max_iterations; ++it) {
      f.gradient(y, grad);
      r.residual = grad.norm();
      r.iterations = it;
      if (history) history->push_back(r.residual);
      // An overflowing load (a force of 1e300 N) makes the scale infinite, and every residual would pass the test.
      if (!std::isfinite(r.residual) || !std::isfinite(f.force_scale())) break;
      if (r.residual <= opt.tolerance * std::max(f.force_scale(), 1e-300)) {
        r.converged = true;
        break;
      }
      // Modified Newton: keep the last factorisation while it still reduces the residual at least fourfold per
      // iteration; refactorise when it does not, when it gives no descent, or when its line search fails.
      const bool reuse = !cg() && opt.reuse_factorization && have_factor && r.residual <= 0.25 * previous;
      if (!step_direction(f, y, it, r.residual, reuse)) break;
      const bool kept = reuse || preconditioned;  // the direction came from the kept factorisation
      previous = kept ? r.residual : std::numeric_limits<double>::infinity();
      double slope = grad.dot(delta);
      if (!(slope < 0.0) && kept) {
        have_factor = false;
        continue;
      }
      if (!(slope < 0.0)) {  // no descent from the (refined) direction: steepest descent
        delta = -grad;
        slope = -grad.squaredNorm();
      }
      if (is_round_off_step(delta, opt, f.size())) {
        y += delta;
        f.gradient(y, grad);
        r.residual = grad.norm();
        r.iterations = it + 1;
        r.converged = true;
        break;
      }
      if (line_search(f, y, slope, r.residual)) {
        y = trial;
      } else if (kept) {
        have_factor = false;
      } else {
        break;
      }
    }
    if (!r.converged) {
      f.gradient(y, grad);
      r.residual = grad.norm();
      r.converged = std::isfinite(r.residual) && std::isfinite(f.force_scale()) &&
                    r.residual <= opt.tolerance * std::max(f.force_scale(), 1e-300);
      r.iterations = it;  // the limit, or where no step could be taken
    }
    r.linear_iterations = cg_iterations;
    return r;
  }
};

NewtonSolver::NewtonSolver(const NewtonOptions& options) : m(std::make_unique<Impl>(options)) {
  if (options.max_iterations < 1 || !(options.tolerance > 0.0) || !(options.step_tolerance >= 0.0) ||
      !(options.cg_tolerance > 0.0 && options.cg_tolerance < 1.0))
    throw InvalidArgument(
        "Newton needs at least 1 iteration, a tolerance > 0, a step tolerance >= 0 and a CG tolerance in (0, 1)");
}
NewtonSolver::~NewtonSolver() = default;
NewtonSolver::NewtonSolver(NewtonSolver&&) noexcept = default;
NewtonSolver& NewtonSolver::operator=(NewtonSolver&&) noexcept = default;

NewtonReport NewtonSolver::solve(NewtonObjective& f, VecX& z, std::vector<double>* residual_history) {
  return m->solve(f, z, residual_history);
}

bool NewtonSolver::direction(NewtonObjective& f, const VecX& z, const VecX& gradient, double cg_tolerance,
                             VecX& delta) {
  m->cg_iterations = 0;
  const bool ok = m->direction(f, z, gradient, cg_tolerance, delta);
  m->have_factor = false;
  return ok;
}

bool NewtonSolver::factorize_at(NewtonObjective& f, const VecX& z) {
  if (m->cg()) throw InvalidArgument("NewtonSolver::factorize_at needs the cholesky linear solver");
  m->have_factor = m->factorize(f.newton_matrix(z, false));
  return m->have_factor;
}

void NewtonSolver::invalidate() {
  m->have_factor = false;
  m->cg_r.resize(0);
  m->cg_pattern_nonzeros = -1;
}

const NewtonOptions& NewtonSolver::options() const { return m->opt; }
long NewtonSolver::linear_iterations() const { return m->cg_iterations; }
double NewtonSolver::factorization_seconds() const { return m->factor_seconds; }
int NewtonSolver::factorizations() const { return m->factor_count; }
std::string_view NewtonSolver::backend_name() const { return m->cg() ? "cg" : m->cholesky.backend_name(); }

}  // namespace hooke::solve
