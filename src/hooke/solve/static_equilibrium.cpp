#include <chrono>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/core/log.hpp>
#include <hooke/model/hessian_assembly.hpp>
#include <memory>
#include <hooke/solve/detail/reduce.hpp>
#include <hooke/solve/stability.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <sstream>

namespace hooke::solve {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::string format_double(double v) {
  std::ostringstream s;
  s.precision(4);
  s << v;
  return s.str();
}

// Newton's method at one load factor, from x (updated in place). Returns true when converged.
struct NewtonState {
  const model::Problem& problem;
  const detail::FreeMap& map;
  const NewtonOptions& options;
  SolveReport& report;
  SparseCholesky chol;
  SparseMatrix identity;
  double size = 1.0;  // extent of the body, m
  std::unique_ptr<model::HessianAssembly> assembly = nullptr;  // the Hessian's pattern, built once, refilled per iteration

  // Free-DOF residual r = dE/dx - lambda f and the force scale for the convergence test.
  VecX residual(const VecX& x, double lambda, double& scale) {
    const auto t0 = Clock::now();
    const VecX g = problem.model->gradient(x);
    report.assembly_seconds += seconds_since(t0);
    const VecX full = g - lambda * problem.external_force;
    scale = std::max((lambda * problem.external_force).norm(), g.norm());
    return map.restrict(full);
  }

  SparseMatrix tangent(const VecX& x) {
    const auto t0 = Clock::now();
    if (!assembly) assembly = std::make_unique<model::HessianAssembly>(*problem.model);
    assembly->assemble(x, options.project_psd);
    SparseMatrix h = map.restrict(assembly->matrix());
    report.assembly_seconds += seconds_since(t0);
    return h;
  }

  bool factorize(const SparseMatrix& a) {
    const auto t0 = Clock::now();
    const bool ok = chol.factorize(a);
    report.factorization_seconds += seconds_since(t0);
    return ok;
  }

  bool solve_step(VecX& x, double lambda) {
    for (int it = 0; it < options.max_iterations; ++it) {
      double scale = 0.0;
      const VecX r = residual(x, lambda, scale);
      const double rnorm = r.norm();
      report.residual_history.push_back(rnorm);
      report.residual = rnorm;
      if (!std::isfinite(rnorm)) return false;
      if (rnorm <= options.tolerance * std::max(scale, 1e-300)) return true;
      ++report.iterations;
      SparseMatrix h = tangent(x);
      bool ok = factorize(h);
      // Indefinite tangent (compressed springs, a buckling body): Levenberg shift until positive definite.
      double tau = 1e-8 * h.diagonal().cwiseAbs().maxCoeff();
      for (int k = 0; !ok && k < 30; ++k, tau *= 10.0) ok = factorize(SparseMatrix(h + tau * identity));
      if (!ok) return false;
      VecX d = -chol.solve(r);
      if (!problem.model->exact_hessian()) refine_step(x, lambda, r, d);
      double slope = r.dot(d);
      if (!(slope < 0.0)) {
        d = -r;
        slope = -r.squaredNorm();
      }
      // A Newton step below the round-off scale of the positions: converged (the force test alone cannot tell
      // at tiny loads, where the residual is round-off noise).
      if (d.cwiseAbs().maxCoeff() <= options.step_tolerance * size) {
        for (int i = 0; i < map.size(); ++i) x(map.free[static_cast<size_t>(i)]) += d(i);
        return true;
      }
      // Backtracking line search on the total potential energy.
      auto trial_at = [&](double alpha) {
        VecX t = x;
        for (int i = 0; i < map.size(); ++i) t(map.free[static_cast<size_t>(i)]) += alpha * d(i);
        return t;
      };
      double alpha = 1.0;
      bool accepted = false;
      if (!problem.model->conservative()) {
        // No potential (e.g. the surface model's blended anchors): backtrack on the residual norm, with the
        // blocks' symmetric Jacobian approximations as the Newton matrix (a quasi-Newton iteration).
        for (int ls = 0; ls < 40 && !accepted; ++ls, alpha *= 0.5) {
          const VecX t = trial_at(alpha);
          double s = 0.0;
          const double rt = residual(t, lambda, s).norm();
          if (std::isfinite(rt) && rt <= (1.0 - 1e-4 * alpha) * rnorm) {
            x = t;
            accepted = true;
          }
        }
        if (!accepted) return false;
        continue;
      }
      const double pi0 = model::potential_energy(problem, x, lambda);
      for (int ls = 0; ls < 40; ++ls, alpha *= 0.5) {
        const VecX t = trial_at(alpha);
        const double pi = model::potential_energy(problem, t, lambda);
        if (std::isfinite(pi) && pi <= pi0 + 1e-4 * alpha * slope) {
          x = t;
          accepted = true;
          break;
        }
        // Near the solution the energy decrease drowns in round-off; a smaller residual is then enough.
        if (std::isfinite(pi) && std::abs(pi - pi0) <= 1e-12 * std::abs(pi0)) {
          double s = 0.0;
          if (residual(t, lambda, s).norm() < rnorm) {
            x = t;
            accepted = true;
            break;
          }
        }
      }
      if (!accepted) return false;
    }
    double scale = 0.0;
    report.residual = residual(x, lambda, scale).norm();
    return report.residual <= options.tolerance * std::max(scale, 1e-300);
  }

  // Without a potential the assembled matrix S is only the symmetric part of the blocks' Jacobians (and drops
  // global rank-one couplings): solve J d = -r by GMRES (Saad, Iterative Methods, Alg. 6.9) right-
  // preconditioned with S^-1 (the existing factor), J v from a forward difference of the residual (one force
  // evaluation per iteration), to |r + J d| <= 1e-6 |r| or 40 iterations; keeps the plain S^-1 step when that
  // is better.
  void refine_step(const VecX& x, double lambda, const VecX& r, VecX& d) {
    const double beta = r.norm();
    if (!(beta > 0.0)) return;
    auto jacobian_times = [&](const VecX& v) {
      const double vmax = v.cwiseAbs().maxCoeff();
      if (!(vmax > 0.0)) return VecX(VecX::Zero(v.size()));
      const double eps = 1e-7 * size / vmax;
      VecX t = x;
      for (int i = 0; i < map.size(); ++i) t(map.free[static_cast<size_t>(i)]) += eps * v(i);
      double s = 0.0;
      return VecX((residual(t, lambda, s) - r) / eps);
    };
    const int m = std::min(40, map.size());
    Eigen::MatrixXd basis(map.size(), m + 1), hess = Eigen::MatrixXd::Zero(m + 1, m);
    basis.col(0) = -r / beta;
    Eigen::VectorXd best;
    for (int k = 0; k < m; ++k) {
      VecX w = jacobian_times(chol.solve(basis.col(k)));
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
    const VecX candidate = chol.solve(VecX(basis.leftCols(best.size()) * best));
    if ((r + jacobian_times(candidate)).norm() < (r + jacobian_times(d)).norm()) d = candidate;
  }

  // Positive definiteness of the tangent on the free DOFs at x.
  bool stable_at(const VecX& x) { return factorize(tangent(x)); }
};

}  // namespace

std::string_view status_name(SolveStatus status) {
  switch (status) {
    case SolveStatus::kConverged: return "converged";
    case SolveStatus::kNotConverged: return "not-converged";
    case SolveStatus::kUnstable: return "unstable";
    case SolveStatus::kSingular: return "singular";
  }
  return "unknown";
}

void require_converged(const SolveReport& report) {
  if (report.status != SolveStatus::kConverged) throw SolverFailure(report.message);
}

StaticResult linear_static(const model::Problem& problem, const LinearOptions& options) {
  const auto t_start = Clock::now();
  StaticResult result;
  SolveReport& rep = result.report;
  const model::Model& m = *problem.model;
  const detail::FreeMap map(model::free_dofs(problem), m.dof_count());
  rep.free_dofs = map.size();
  VecX x = model::initial_positions(problem);
  const VecX u_prescribed = x - m.rest_positions();

  auto t0 = Clock::now();
  const SparseMatrix k_full = m.hessian(m.rest_positions());
  // Linearised about the rest state: K u = f - g(X) - K u_c, with g(X) the (normally zero) internal force at rest
  // and u_c the prescribed displacements.
  const VecX rhs_full = problem.external_force - m.gradient(m.rest_positions()) - k_full * u_prescribed;
  const SparseMatrix k = map.restrict(k_full);
  rep.assembly_seconds = seconds_since(t0);

  SparseCholesky chol(options.backend);
  rep.backend = std::string(chol.backend_name());
  t0 = Clock::now();
  const bool ok = chol.factorize(k);
  rep.factorization_seconds = seconds_since(t0);
  rep.reference_force = problem.external_force.norm();
  if (!ok) {
    rep.status = SolveStatus::kSingular;
    rep.message = "the stiffness matrix on the " + std::to_string(map.size()) +
                  " free DOFs is not positive definite: the body is not held against rigid motion (fix more nodes)";
    result.positions = x;
    rep.solve_seconds = seconds_since(t_start);
    return result;
  }
  const VecX u = chol.solve(map.restrict(rhs_full));
  for (int i = 0; i < map.size(); ++i) x(map.free[static_cast<size_t>(i)]) += u(i);
  rep.residual = (k * u - map.restrict(rhs_full)).norm();
  rep.iterations = 1;
  rep.load_steps = 1;
  rep.load_factor = 1.0;
  rep.status = SolveStatus::kConverged;
  if (options.estimate_min_eigenvalue) rep.min_eigenvalue = smallest_eigenvalue(k);
  rep.message = "linear solve on " + std::to_string(map.size()) + " DOFs";
  result.positions = std::move(x);
  rep.solve_seconds = seconds_since(t_start);
  return result;
}

StaticResult static_equilibrium(const model::Problem& problem, const NewtonOptions& options) {
  if (options.check_stability && !problem.model->exact_hessian()) {
    // Positive definiteness of an approximate Hessian says nothing about stability.
    NewtonOptions unchecked = options;
    unchecked.check_stability = false;
    StaticResult r = static_equilibrium(problem, unchecked);
    r.report.message += " (stability not checked: the model's Hessian is an approximation)";
    return r;
  }
  const auto t_start = Clock::now();
  StaticResult result;
  SolveReport& rep = result.report;
  const model::Model& m = *problem.model;
  const detail::FreeMap map(model::free_dofs(problem), m.dof_count());
  rep.free_dofs = map.size();
  rep.reference_force = problem.external_force.norm();
  NewtonState newton{problem, map, options, rep, SparseCholesky(options.backend), SparseMatrix(map.size(), map.size())};
  newton.identity.setIdentity();
  {
    const VecX& rest = m.rest_positions();
    newton.size = std::max(rest.maxCoeff() - rest.minCoeff(), 1e-300);
  }
  rep.backend = std::string(newton.chol.backend_name());

  VecX x_stable = model::initial_positions(problem);
  double lambda_stable = 0.0;
  double step = 1.0 / std::max(1, options.initial_load_steps);
  auto finish = [&](SolveStatus status, std::string message) {
    rep.status = status;
    rep.message = std::move(message);
    rep.load_factor = lambda_stable;
    double scale = 0.0;
    rep.residual = newton.residual(x_stable, lambda_stable, scale).norm();
    if (options.check_stability && map.size() > 0) rep.min_eigenvalue = smallest_eigenvalue(newton.tangent(x_stable));
    result.positions = x_stable;
    rep.solve_seconds = seconds_since(t_start);
    return result;
  };

  if (options.check_stability && !newton.stable_at(x_stable))
    return finish(SolveStatus::kSingular,
                  "the tangent stiffness at the start is not positive definite: the body is "
                  "not held against rigid motion, or starts in an unstable state");

  if (options.start.size() > 0) {
    if (options.start.size() != m.dof_count())
      throw InvalidArgument("static_equilibrium: the initial guess has " + std::to_string(options.start.size()) +
                            " entries, the model " + std::to_string(m.dof_count()) + " DOFs");
    VecX x = x_stable;
    for (const int i : map.free) x(i) = options.start(i);
    if (x.allFinite() && newton.solve_step(x, 1.0) && (!options.check_stability || newton.stable_at(x))) {
      x_stable = std::move(x);
      lambda_stable = 1.0;
      ++rep.load_steps;
    }
  }
  while (lambda_stable < 1.0) {
    const double lambda = std::min(1.0, lambda_stable + step);
    VecX x = x_stable;
    if (!newton.solve_step(x, lambda)) {
      step *= 0.5;
      if (step < options.min_load_step) {
        StaticResult r = finish(SolveStatus::kNotConverged, "Newton did not converge beyond load factor " +
                                                                format_double(lambda_stable) + " (load step below " +
                                                                format_double(options.min_load_step) + ")");
        if (options.check_stability)
          r.report.message += "; the smallest tangent eigenvalue there is " + format_double(r.report.min_eigenvalue) +
                              " N/m (near zero: a limit point, beyond which the body collapses)";
        return r;
      }
      continue;
    }
    if (options.check_stability && !newton.stable_at(x)) {
      // Bracket the load factor where the tangent stops being positive definite.
      double lo = lambda_stable, hi = lambda;
      for (int b = 0; b < options.bisection_steps; ++b) {
        const double mid = 0.5 * (lo + hi);
        VecX xm = x_stable;
        if (newton.solve_step(xm, mid) && newton.stable_at(xm)) {
          lo = mid;
          x_stable = std::move(xm);
          lambda_stable = mid;
        } else {
          hi = mid;
        }
      }
      rep.critical_load_factor = 0.5 * (lo + hi);
      return finish(SolveStatus::kUnstable,
                    "stability is lost at load factor " + format_double(rep.critical_load_factor) + " (between " +
                        format_double(lo) + " and " + format_double(hi) +
                        "): the equilibrium beyond it is unstable (buckling); the state returned is the last "
                        "stable one, at load factor " +
                        format_double(lo));
    }
    x_stable = std::move(x);
    lambda_stable = lambda;
    ++rep.load_steps;
    step = std::min(step * 1.5, 1.0);
  }
  return finish(SolveStatus::kConverged, "converged in " + std::to_string(rep.iterations) + " Newton iterations over " +
                                             std::to_string(rep.load_steps) + " load steps");
}

}  // namespace hooke::solve
