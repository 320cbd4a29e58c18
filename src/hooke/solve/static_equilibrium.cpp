#include <chrono>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/core/log.hpp>
#include <hooke/model/free_map.hpp>
#include <hooke/model/hessian_assembly.hpp>
#include <hooke/solve/detail/sparse_ops.hpp>
#include <hooke/solve/stability.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <sstream>
#include <utility>

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

// Every load of a several-load solve has one entry per DOF. @throws InvalidArgument naming `who`
void require_load_sizes(const char* who, const std::vector<VecX>& loads, Eigen::Index dofs) {
  for (const VecX& f : loads)
    if (f.size() != dofs)
      throw InvalidArgument(std::string(who) + ": a load has " + std::to_string(f.size()) + " entries, the model " +
                            std::to_string(dofs) + " DOFs");
}

// Pi(x) = E(x) - lambda f.(x - X) over the free DOFs of a problem, for NewtonSolver. DOFs that carry no stiffness
// (nodes in no element) are held with the fixed ones.
class StaticObjective final : public NewtonObjective {
 public:
  StaticObjective(const model::Problem& problem, const model::FreeMap& map)
      : m_problem(problem), m_assembly(*problem.model), m_fixed(problem.model->dof_count(), 1) {
    for (const int i : map.free) m_fixed[static_cast<size_t>(i)] = 0;
    const VecX& rest = problem.model->rest_positions();
    m_size = std::max(rest.maxCoeff() - rest.minCoeff(), 1e-300);
    m_model_gradient.setZero(rest.size());
  }
  void set_load_factor(double lambda) { m_lambda = lambda; }
  // The load (flat, N; as problem.external_force) and the report that assembly times go to, until the next call.
  void set_load(const VecX& force, SolveReport& report) {
    m_force = &force;
    m_report = &report;
  }

  bool conservative() const override { return m_problem.model->conservative(); }
  bool exact_hessian() const override { return m_problem.model->exact_hessian(); }
  const std::vector<char>& fixed() const override { return m_fixed; }
  int dim() const override { return m_problem.model->dim(); }
  double size() const override { return m_size; }
  double value(const VecX& z) override { return model::potential_energy(m_problem, z, *m_force, m_lambda); }
  // The convergence test's scale is max(|lambda f|, |dE/dx|) with the internal force over all DOFs: the reactions
  // count where the body is held by prescribed displacements alone.
  void gradient(const VecX& z, VecX& out) override {
    const auto t0 = Clock::now();
    m_problem.model->gradient(z, m_model_gradient, m_problem.interaction_or_null());
    m_report->assembly_seconds += seconds_since(t0);
    out = m_model_gradient - m_lambda * *m_force;
    m_scale = std::max(m_lambda * m_force->norm(), m_model_gradient.norm());
    for (size_t i = 0; i < m_fixed.size(); ++i)
      if (m_fixed[i]) out(static_cast<Eigen::Index>(i)) = 0.0;
  }
  double force_scale() const override { return m_scale; }
  SparseMatrix& newton_matrix(const VecX& z, bool project) override {
    const auto t0 = Clock::now();
    m_assembly.assemble(z, project, m_problem.interaction_or_null());
    detail::constrain(m_assembly.matrix(), m_fixed, 1);
    m_report->assembly_seconds += seconds_since(t0);
    return m_assembly.matrix();
  }
  const std::vector<int>& diagonal() const override { return m_assembly.diagonal(); }

  // Moves the fixed DOFs of x by `jump` (zero on the free DOFs) and the free DOFs by the response of the tangent at
  // x, PSD-projected, to that move: the linear predictor of a step in the prescribed displacements. Where that
  // tangent cannot be factorised the free DOFs stay.
  void predict(VecX& x, const VecX& jump) {
    const auto t0 = Clock::now();
    m_assembly.assemble(x, true, m_problem.interaction_or_null());
    VecX rhs = -(m_assembly.matrix() * jump);
    detail::constrain(m_assembly.matrix(), m_fixed, 1);
    m_report->assembly_seconds += seconds_since(t0);
    for (size_t i = 0; i < m_fixed.size(); ++i)
      if (m_fixed[i]) rhs(static_cast<Eigen::Index>(i)) = 0.0;
    x += jump;
    const auto t1 = Clock::now();
    if (m_predictor.factorize(m_assembly.matrix())) x += m_predictor.solve(rhs);
    m_report->factorization_seconds += seconds_since(t1);
    ++m_report->factorizations;
  }

  // The exact tangent restricted to the free DOFs (for the stability test and the smallest eigenvalue).
  SparseMatrix free_tangent(const VecX& z, const model::FreeMap& map) {
    const auto t0 = Clock::now();
    m_assembly.assemble(z, false, m_problem.interaction_or_null());
    SparseMatrix h = map.restrict(m_assembly.matrix());
    m_report->assembly_seconds += seconds_since(t0);
    return h;
  }

 private:
  const model::Problem& m_problem;
  model::HessianAssembly m_assembly;  // the Hessian's pattern, built once for the whole solve
  std::vector<char> m_fixed;
  const VecX* m_force = nullptr;
  SolveReport* m_report = nullptr;
  double m_size = 1.0, m_lambda = 1.0, m_scale = 0.0;
  VecX m_model_gradient;
  SparseCholesky m_predictor;
};

// Newton at one load factor from x (updated in place), and the stability test, over one objective; the load and
// the report are those of begin(), so that one solver (and its kept factorisation) serves several loads.
struct LoadStepper {
  LoadStepper(StaticObjective& f, const model::FreeMap& free, const NewtonOptions& options)
      : objective(f), map(free), newton(options), stability_factor(options.backend) {}

  StaticObjective& objective;
  const model::FreeMap& map;
  SolveReport* report = nullptr;
  NewtonSolver newton;
  SparseCholesky stability_factor;

  // A new load (as problem.external_force) from the start state x0, its outcome into `r`.
  void begin(const VecX& force, const VecX& x0, SolveReport& r) {
    report = &r;
    objective.set_load(force, r);
    x_stable = x0;
    lambda_stable = 0.0;
  }

  // Under ramp_prescribed: the prescribed displacements of the fixed DOFs (u_c, zero elsewhere) and the rest
  // positions they are taken from; empty otherwise.
  VecX ramp, rest;

  // The fixed DOFs' positions at load factor lambda.
  VecX held_at(double lambda) const { return rest + lambda * ramp; }

  bool solve_step(VecX& x, double lambda) {
    if (ramp.size() > 0) {
      VecX jump = held_at(lambda) - x;
      for (const int i : map.free) jump(i) = 0.0;
      if (jump.lpNorm<Eigen::Infinity>() > 0.0) objective.predict(x, jump);
    }
    objective.set_load_factor(lambda);
    const NewtonReport r = newton.solve(objective, x, &report->residual_history);
    report->iterations += r.iterations;
    report->residual = r.residual;
    // A state of infinite energy (an inverted element, a node inside a contact tool) is no equilibrium, whatever its
    // gradient: the barrier's gradient is not defined there.
    return r.converged && (!objective.conservative() || std::isfinite(objective.value(x)));
  }

  double residual(const VecX& x, double lambda) {
    objective.set_load_factor(lambda);
    VecX g(x.size());
    objective.gradient(x, g);
    return g.norm();
  }

  // Positive definiteness of the tangent on the free DOFs at x.
  bool stable_at(const VecX& x) {
    const auto t0 = Clock::now();
    const bool ok = stability_factor.factorize(objective.free_tangent(x, map));
    report->factorization_seconds += seconds_since(t0);
    ++report->factorizations;
    return ok;
  }

  // The last accepted state and its load factor.
  VecX x_stable;
  double lambda_stable = 0.0;

  void accept(VecX x, double lambda) {
    x_stable = std::move(x);
    lambda_stable = lambda;
    ++report->load_steps;
  }

  // Newton at the full load from an initial guess (its free DOFs); accepted when it converges (stably).
  void try_start(const VecX& start, bool check_stability) {
    VecX x = ramp.size() > 0 ? held_at(1.0) : x_stable;
    for (const int i : map.free) x(i) = start(i);
    if (x.allFinite() && solve_step(x, 1.0) && (!check_stability || stable_at(x))) accept(std::move(x), 1.0);
  }

  // Stability is lost between lambda_stable and `unstable`: bisects `steps` times, accepting the stable states
  // on the way. Returns the bracket [lo, hi].
  std::pair<double, double> bracket_instability(double unstable, int steps) {
    double lo = lambda_stable, hi = unstable;
    for (int b = 0; b < steps; ++b) {
      const double mid = 0.5 * (lo + hi);
      VecX xm = x_stable;
      if (solve_step(xm, mid) && stable_at(xm)) {
        lo = mid;
        x_stable = std::move(xm);
        lambda_stable = mid;
      } else {
        hi = mid;
      }
    }
    return {lo, hi};
  }
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

std::vector<StaticResult> linear_statics(const model::Problem& problem, const std::vector<VecX>& loads,
                                         const LinearOptions& options) {
  const auto t_start = Clock::now();
  const model::Model& m = *problem.model;
  require_load_sizes("linear_statics", loads, m.dof_count());
  const model::FreeMap map(model::free_dofs(problem), m.dof_count());
  const VecX x0 = model::initial_positions(problem);
  const VecX u_prescribed = x0 - m.rest_positions();

  auto t0 = Clock::now();
  const SparseMatrix k_full = m.hessian(m.rest_positions(), false, problem.interaction_or_null());
  // Linearised about the rest state: K u = f - g(X) - K u_c, with g(X) the (normally zero) internal force at rest
  // and u_c the prescribed displacements.
  const VecX internal = m.gradient(m.rest_positions(), problem.interaction_or_null()) + k_full * u_prescribed;
  const SparseMatrix k = map.restrict(k_full);
  const double assembly = seconds_since(t0);

  SparseCholesky chol(options.backend);
  t0 = Clock::now();
  const bool ok = chol.factorize(k);
  const double factorization = seconds_since(t0);
  const double min_eigenvalue = ok && options.estimate_min_eigenvalue ? smallest_eigenvalue(k) : 0.0;
  std::vector<StaticResult> out;
  for (size_t j = 0; j < loads.size(); ++j) {
    StaticResult result;
    SolveReport& rep = result.report;
    rep.free_dofs = map.size();
    rep.backend = std::string(chol.backend_name());
    rep.reference_force = loads[j].norm();
    if (j == 0) {  // the shared assembly and factorisation count for the first load
      rep.assembly_seconds = assembly;
      rep.factorization_seconds = factorization;
      rep.factorizations = 1;
    }
    result.positions = x0;
    if (!ok) {
      rep.status = SolveStatus::kSingular;
      rep.message = "the stiffness matrix on the " + std::to_string(map.size()) +
                    " free DOFs is not positive definite: the body is not held against rigid motion (fix more nodes)";
    } else {
      const VecX rhs = map.restrict(VecX(loads[j] - internal));
      const VecX u = chol.solve(rhs);
      for (int i = 0; i < map.size(); ++i) result.positions(map.free[static_cast<size_t>(i)]) += u(i);
      rep.residual = (k * u - rhs).norm();
      rep.iterations = 1;
      rep.load_steps = 1;
      rep.load_factor = 1.0;
      rep.status = SolveStatus::kConverged;
      rep.min_eigenvalue = min_eigenvalue;
      rep.message = "linear solve on " + std::to_string(map.size()) + " DOFs";
    }
    rep.solve_seconds = seconds_since(t_start);
    out.push_back(std::move(result));
  }
  return out;
}

StaticResult linear_static(const model::Problem& problem, const LinearOptions& options) {
  return std::move(linear_statics(problem, {problem.external_force}, options).front());
}

namespace {

// Load stepping under the load `newton` began with: the body of static_equilibrium for one load. `start_stable`:
// the start state's stability test, already made (once for all loads).
StaticResult solve_load(LoadStepper& newton, const StaticOptions& options, bool start_stable) {
  const auto t_start = Clock::now();
  StaticResult result;
  SolveReport& rep = *newton.report;
  const double factorization_before = newton.newton.factorization_seconds();
  const int factorizations_before = newton.newton.factorizations();
  const VecX& x_stable = newton.x_stable;
  const double& lambda_stable = newton.lambda_stable;
  const model::FreeMap& map = newton.map;
  double step = 1.0 / std::max(1, options.initial_load_steps);
  auto finish = [&](SolveStatus status, std::string message) {
    rep.status = status;
    rep.message = std::move(message);
    rep.load_factor = lambda_stable;
    rep.residual = newton.residual(x_stable, lambda_stable);
    if (options.check_stability && map.size() > 0 &&
        (options.estimate_min_eigenvalue || status != SolveStatus::kConverged))
      rep.min_eigenvalue = smallest_eigenvalue(newton.objective.free_tangent(x_stable, map));
    rep.factorization_seconds += newton.newton.factorization_seconds() - factorization_before;
    rep.factorizations += newton.newton.factorizations() - factorizations_before;
    result.positions = x_stable;
    rep.solve_seconds += seconds_since(t_start);
    result.report = std::move(rep);
    return result;
  };

  // A given start is tried first, at the full load: where it converges to a stable state the base state (rest with
  // the held DOFs where they are prescribed, which under a deep press is far from any equilibrium) is never needed.
  if (options.start.size() > 0) newton.try_start(options.start, options.check_stability);
  if (!start_stable && lambda_stable < 1.0)
    return finish(SolveStatus::kSingular,
                  "the tangent stiffness at the start is not positive definite: the body is "
                  "not held against rigid motion, or starts in an unstable state");

  // A step whose state moved kBranchJump times faster per unit load than the last accepted one has left the path:
  // past a limit point Newton can land on a far equilibrium of another branch (a snap-through), stable but not the
  // continuation of the loading. Such a step is refused like a failed one, so the limit point is reported instead.
  constexpr double kBranchJump = 10.0;
  double rate = -1.0;  // |x - x_stable| / (lambda - lambda_stable) of the last accepted step
  bool jumped = false;
  while (lambda_stable < 1.0) {
    const double lambda = std::min(1.0, lambda_stable + step);
    VecX x = x_stable;
    bool ok = newton.solve_step(x, lambda);
    const double step_rate = (x - x_stable).norm() / (lambda - lambda_stable);
    if (ok && rate > 0.0 && step_rate > kBranchJump * rate) {
      ok = false;
      jumped = true;
    }
    if (!ok) {
      step *= 0.5;
      if (step < options.min_load_step) {
        StaticResult r = finish(SolveStatus::kNotConverged,
                                "Newton did not converge beyond load factor " + format_double(lambda_stable) +
                                    " (load step below " + format_double(options.min_load_step) + ")" +
                                    (jumped ? "; beyond it the state jumps to another branch" : ""));
        if (options.check_stability)
          r.report.message += "; the smallest tangent eigenvalue there is " + format_double(r.report.min_eigenvalue) +
                              " N/m (near zero: a limit point, beyond which the body collapses)";
        return r;
      }
      continue;
    }
    if (options.check_stability && !newton.stable_at(x)) {
      const auto [lo, hi] = newton.bracket_instability(lambda, options.bisection_steps);
      rep.critical_load_factor = 0.5 * (lo + hi);
      return finish(SolveStatus::kUnstable,
                    "stability is lost at load factor " + format_double(rep.critical_load_factor) + " (between " +
                        format_double(lo) + " and " + format_double(hi) +
                        "): the equilibrium beyond it is unstable (buckling); the state returned is the last "
                        "stable one, at load factor " +
                        format_double(lo));
    }
    rate = step_rate;
    newton.accept(std::move(x), lambda);
    step = std::min(step * 1.5, 1.0);
  }
  const auto count = [](int n, const char* what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); };
  if (rep.iterations == 0)  // a linear problem started at its solution, or no load
    return finish(SolveStatus::kConverged, "the start already is the equilibrium (residual within the tolerance)");
  return finish(SolveStatus::kConverged, "converged in " + count(rep.iterations, "Newton iteration") + " over " +
                                             count(rep.load_steps, "load step"));
}

}  // namespace

std::vector<StaticResult> static_equilibria(const model::Problem& problem, const std::vector<VecX>& loads,
                                            const StaticOptions& options) {
  if (options.check_stability && !problem.model->exact_hessian()) {
    // Positive definiteness of an approximate Hessian says nothing about stability.
    StaticOptions unchecked = options;
    unchecked.check_stability = false;
    std::vector<StaticResult> r = static_equilibria(problem, loads, unchecked);
    for (StaticResult& one : r)
      one.report.message += " (stability not checked: the model's Hessian is an approximation)";
    return r;
  }
  const model::Model& m = *problem.model;
  require_load_sizes("static_equilibria", loads, m.dof_count());
  if (options.start.size() > 0 && options.start.size() != m.dof_count())
    throw InvalidArgument("static_equilibrium: the initial guess has " + std::to_string(options.start.size()) +
                          " entries, the model " + std::to_string(m.dof_count()) + " DOFs");
  if (options.start.size() > 0 && loads.size() > 1)
    throw InvalidArgument("static_equilibria: an initial guess is for one load, not " + std::to_string(loads.size()));
  const model::FreeMap map(model::free_dofs(problem), m.dof_count());
  StaticObjective objective(problem, map);
  LoadStepper newton(objective, map, options.newton);
  VecX x0 = model::initial_positions(problem);
  if (options.ramp_prescribed) {
    // The held DOFs start at rest and reach their prescribed positions at load factor 1.
    newton.rest = m.rest_positions();
    newton.ramp = x0 - newton.rest;
    for (const int i : map.free) newton.ramp(i) = 0.0;
    for (int i = 0; i < m.dof_count(); ++i)
      if (!problem.fixed_dofs[static_cast<size_t>(i)]) newton.ramp(i) = 0.0;
    x0 = newton.rest;
  }
  std::vector<StaticResult> out;
  bool start_stable = true;
  for (size_t k = 0; k < loads.size(); ++k) {
    SolveReport rep;
    rep.free_dofs = map.size();
    rep.reference_force = loads[k].norm();
    rep.backend = std::string(newton.newton.backend_name());
    newton.begin(loads[k], x0, rep);
    if (k == 0 && options.check_stability) {  // the same start state, supports and tangent for every load
      const auto t0 = Clock::now();
      if (options.newton.reuse_factorization && options.newton.linear_solver == NewtonLinearSolver::kCholesky) {
        // The Newton matrix at the start is the tangent there with identity rows and columns on the held DOFs:
        // positive definite exactly when the tangent on the free DOFs is, and modified Newton starts from it.
        start_stable = newton.newton.factorize_at(objective, x0);
        rep.factorization_seconds += seconds_since(t0);
        ++rep.factorizations;
      } else {
        start_stable = newton.stable_at(x0);
      }
      rep.solve_seconds = seconds_since(t0);
    }
    out.push_back(solve_load(newton, options, start_stable));
  }
  return out;
}

StaticResult static_equilibrium(const model::Problem& problem, const StaticOptions& options) {
  return std::move(static_equilibria(problem, {problem.external_force}, options).front());
}

}  // namespace hooke::solve
