#include <Eigen/IterativeLinearSolvers>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/solve/detail/reduce.hpp>
#include <hooke/solve/simulator.hpp>
#include <hooke/solve/sparse_cholesky.hpp>
#include <hooke/springs/spring_block.hpp>
#include <limits>
#include <string>

namespace hooke::solve {
namespace {

constexpr std::string_view kNames[] = {"symplectic-euler", "velocity-verlet", "implicit-euler", "local-global",
                                       "quasi-static"};

std::vector<int> unfixed(const model::Problem& p) {
  std::vector<int> free;
  for (size_t i = 0; i < p.fixed_dofs.size(); ++i)
    if (!p.fixed_dofs[i]) free.push_back(static_cast<int>(i));
  return free;
}

// Liu et al. 2013: the spring part of the incremental potential as min over directions d_s, |d_s| = l0_s, of
// sum_s k_s/2 |x_i - x_j - d_s|^2, which makes the global step one constant linear system.
struct Springs {
  std::vector<std::array<int, 2>> pairs;
  VecX k, l0;
};

}  // namespace

Integrator integrator_from_name(std::string_view name) {
  for (size_t i = 0; i < std::size(kNames); ++i)
    if (kNames[i] == name) return static_cast<Integrator>(i);
  throw InvalidArgument("unknown integrator '" + std::string(name) +
                        "' (use symplectic-euler, velocity-verlet, implicit-euler, local-global, quasi-static)");
}

std::string_view integrator_name(Integrator integrator) { return kNames[static_cast<size_t>(integrator)]; }

NewtonLinearSolver newton_linear_solver_from_name(std::string_view name) {
  if (name == "cholesky") return NewtonLinearSolver::kCholesky;
  if (name == "cg") return NewtonLinearSolver::kConjugateGradient;
  throw InvalidArgument("unknown linear solver '" + std::string(name) + "' (use cholesky or cg)");
}

struct Simulator::Impl {
  model::Problem problem;
  Dynamics dyn;
  SimulatorOptions opt;
  detail::FreeMap free;
  VecX x, v, x_n, f_total, elastic_gradient;
  bool gradient_valid = false;
  double time_s = 0.0;
  SparseMatrix k0, damping;  // K at rest; D = alpha M + beta K0 (full DOFs), empty when undamped
  SparseCholesky cholesky;
  bool have_factor = false;  // `cholesky` holds a factorisation of an earlier Newton matrix
  double factor_w = -1.0, factor_dt = -1.0;
  VecX cg_guess;
  Springs springs;    // local-global only
  SparseMatrix lg_a;  // M/dt^2 + D/dt + L, full DOFs
  SparseCholesky lg_factor;
  double lg_dt = -1.0;
  Probe probe;
  VecX grab_positions;           // positions of the probe nodes' DOFs when grabbed
  std::vector<char> base_fixed;  // fixed DOFs of the problem without the probe

  // Rebuilds the free-DOF map after the fixed set changed; factorisations are redone on their next use.
  void refix() {
    free = detail::FreeMap(unfixed(problem), model().dof_count());
    lg_dt = -1.0;
    have_factor = false;
    cg_guess.resize(0);
    stable_dt_cache = -1.0;
  }

  Impl(model::Problem p, Dynamics d, SimulatorOptions o)
      : problem(std::move(p)), dyn(std::move(d)), opt(o), free(unfixed(problem), problem.model->dof_count()) {}

  const model::Model& model() const { return *problem.model; }

  const SparseMatrix& rest_stiffness() {
    if (k0.rows() == 0) k0 = model().hessian(model().rest_positions());
    return k0;
  }

  // Positions of the fixed DOFs now (prescribed, else rest).
  void apply_prescribed(VecX& y) const {
    const bool given = problem.prescribed_positions.size() == y.size();
    for (size_t i = 0; i < problem.fixed_dofs.size(); ++i)
      if (problem.fixed_dofs[i])
        y(static_cast<Eigen::Index>(i)) = given ? problem.prescribed_positions(static_cast<Eigen::Index>(i))
                                                : model().rest_positions()(static_cast<Eigen::Index>(i));
  }

  void update_loads() {
    f_total = problem.external_force.size() == x.size() ? problem.external_force : VecX::Zero(x.size());
    const int d = model().dim();
    if (dyn.gravity.size() == d)
      for (Eigen::Index i = 0; i < x.size(); ++i) f_total(i) += dyn.mass(i) * dyn.gravity(i % d);
    if (!probe.nodes.empty() && !probe.drive_position)
      for (int node : probe.nodes)
        f_total.segment(d * node, d) += probe.force / static_cast<double>(probe.nodes.size());
  }

  // A driving probe's nodes are fixed DOFs: their targets are grab position + offset.
  void update_probe_targets() {
    if (probe.nodes.empty() || !probe.drive_position) return;
    const int d = model().dim();
    if (problem.prescribed_positions.size() != x.size()) problem.prescribed_positions = model().rest_positions();
    for (size_t k = 0; k < probe.nodes.size(); ++k)
      problem.prescribed_positions.segment(d * probe.nodes[k], d) =
          grab_positions.segment(d * static_cast<Eigen::Index>(k), d) + probe.offset;
  }

  VecX probe_force() {
    const int d = model().dim();
    VecX out = VecX::Zero(d);
    if (probe.nodes.empty()) return out;
    if (!probe.drive_position) return -probe.force;
    const VecX g = model().gradient(x) - f_total;
    for (int node : probe.nodes) out -= g.segment(d * node, d);
    return out;
  }

  // Acceleration on the free DOFs (zero on fixed), from the elastic gradient at x and velocity w.
  VecX acceleration(const VecX& w) {
    if (!gradient_valid) {
      elastic_gradient = model().gradient(x);
      gradient_valid = true;
    }
    VecX f = f_total - elastic_gradient;
    if (dyn.mass_damping > 0.0) f -= dyn.mass_damping * dyn.mass.cwiseProduct(w);
    if (dyn.stiffness_damping > 0.0) f -= dyn.stiffness_damping * (rest_stiffness() * w);
    VecX a = VecX::Zero(x.size());
    for (int i : free.free) a(i) = f(i) / dyn.mass(i);
    return a;
  }

  StepReport explicit_step(double dt, bool verlet) {
    StepReport r;
    r.beyond_stable_dt = dt > stable_dt();
    VecX x_target = x;
    apply_prescribed(x_target);
    v += (verlet ? 0.5 : 1.0) * dt * acceleration(v);  // (half) kick
    for (int i : free.free) x(i) += dt * v(i);         // drift
    fixed_motion(x_target, dt);
    gradient_valid = false;
    if (verlet) v += 0.5 * dt * acceleration(v);
    return r;
  }

  // Moves the fixed DOFs to their targets, with velocity (target - old) / dt.
  void fixed_motion(const VecX& target, double dt) {
    for (size_t i = 0; i < problem.fixed_dofs.size(); ++i)
      if (problem.fixed_dofs[i]) {
        const auto k = static_cast<Eigen::Index>(i);
        v(k) = (target(k) - x(k)) / dt;
        x(k) = target(k);
      }
  }

  double stable_dt_cache = -1.0;
  double stable_dt() {
    if (stable_dt_cache >= 0.0) return stable_dt_cache;
    const SparseMatrix& k = rest_stiffness();
    const int n = free.size();
    if (n == 0) return stable_dt_cache = std::numeric_limits<double>::infinity();
    // Power iteration on M^-1/2 K M^-1/2 (symmetric, same spectrum as M^-1 K) on the free DOFs.
    VecX inv_sqrt_m(n), z = VecX::Ones(n), full = VecX::Zero(x.size());
    for (int i = 0; i < n; ++i) inv_sqrt_m(i) = 1.0 / std::sqrt(dyn.mass(free.free[static_cast<size_t>(i)]));
    for (int i = 0; i < n; ++i) z(i) += 0.1 * std::sin(1.0 + i);  // break symmetries
    double lambda = 0.0;
    for (int it = 0; it < 200; ++it) {
      z.normalize();
      full.setZero();
      for (int i = 0; i < n; ++i) full(free.free[static_cast<size_t>(i)]) = inv_sqrt_m(i) * z(i);
      const VecX kz = k * full;
      VecX y(n);
      for (int i = 0; i < n; ++i) y(i) = inv_sqrt_m(i) * kz(free.free[static_cast<size_t>(i)]);
      lambda = z.dot(y);
      z = y;
      if (z.norm() == 0.0) break;
    }
    return stable_dt_cache = lambda > 0.0 ? 2.0 / std::sqrt(lambda) : std::numeric_limits<double>::infinity();
  }

  // Incremental potential of implicit Euler (w = 1/dt^2) or the static potential (w = 0) at y.
  double objective(const VecX& y, const VecX& x_hat, double w, double dt) const {
    const double e = model().energy(y);
    if (!std::isfinite(e)) return e;
    double phi = e - f_total.dot(y - model().rest_positions());
    if (w > 0.0) phi += 0.5 * w * (y - x_hat).cwiseAbs2().dot(dyn.mass);
    if (damping.rows() > 0 && dt > 0.0) phi += 0.5 / dt * (y - x_n).dot(damping * (y - x_n));
    return phi;
  }

  VecX objective_gradient(const VecX& y, const VecX& x_hat, double w, double dt) const {
    VecX g = model().gradient(y) - f_total;
    if (w > 0.0) g += w * dyn.mass.cwiseProduct(y - x_hat);
    if (damping.rows() > 0 && dt > 0.0) g += damping * (y - x_n) / dt;
    return g;
  }

  // Newton's method with backtracking line search on the objective; y holds the start and the result.
  StepReport newton(VecX& y, const VecX& x_hat, double w, double dt) {
    StepReport r;
    const double scale =
        free.restrict(f_total).norm() + free.restrict(objective_gradient(y, x_hat, w, dt)).norm() + 1e-30;
    double phi = objective(y, x_hat, w, dt);
    double previous = std::numeric_limits<double>::infinity();
    int it = 0;
    for (; it < opt.max_newton_iterations; ++it) {
      const VecX g = objective_gradient(y, x_hat, w, dt);
      const VecX gf = free.restrict(g);
      r.residual = gf.norm();
      r.iterations = it;
      if (r.residual <= opt.newton_tolerance * scale) return r;
      // Modified Newton: keep the last factorisation (of an earlier iterate, possibly an earlier step) while it
      // still reduces the residual at least fourfold per iteration; refactorise when it does not, when it
      // gives no descent, or when its line search fails.
      const bool reuse = opt.linear_solver == NewtonLinearSolver::kCholesky && opt.reuse_factorization && have_factor &&
                         factor_w == w && factor_dt == dt && r.residual <= 0.25 * previous;
      VecX delta;
      if (reuse) {
        delta = cholesky.solve(-gf);
      } else {
        SparseMatrix h = free.restrict(model().hessian(y, opt.project_psd));
        if (damping.rows() > 0 && dt > 0.0) h += free.restrict(damping) / dt;
        for (int i = 0; i < free.size(); ++i) h.coeffRef(i, i) += w * dyn.mass(free.free[static_cast<size_t>(i)]);
        delta = solve_linear(h, -gf);
        have_factor = opt.linear_solver == NewtonLinearSolver::kCholesky;
        factor_w = w;
        factor_dt = dt;
      }
      previous = reuse ? r.residual : std::numeric_limits<double>::infinity();
      double alpha = 1.0, slope = gf.dot(delta);
      if (!(slope < 0.0)) {
        if (!reuse) break;
        have_factor = false;
        continue;
      }
      VecX trial = y;
      bool accepted = false;
      for (int ls = 0; ls < 40; ++ls) {
        trial = y;
        for (int i = 0; i < free.size(); ++i) trial(free.free[static_cast<size_t>(i)]) += alpha * delta(i);
        const double p = objective(trial, x_hat, w, dt);
        if (std::isfinite(p) && p <= phi + 1e-4 * alpha * slope) {
          phi = p;
          accepted = true;
          break;
        }
        alpha *= 0.5;
      }
      if (!accepted) {
        if (!reuse) break;
        have_factor = false;
        continue;
      }
      y = trial;
      if (alpha * delta.cwiseAbs().maxCoeff() < 1e-15 * (1.0 + y.cwiseAbs().maxCoeff())) {
        r.iterations = it + 1;
        r.residual = free.restrict(objective_gradient(y, x_hat, w, dt)).norm();
        return r;
      }
    }
    r.residual = free.restrict(objective_gradient(y, x_hat, w, dt)).norm();
    r.converged = r.residual <= opt.newton_tolerance * scale;
    r.iterations = it;  // the limit, or where the line search found no descent
    return r;
  }

  VecX solve_linear(SparseMatrix& h, const VecX& rhs) {
    if (opt.linear_solver == NewtonLinearSolver::kConjugateGradient) {
      Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper> cg(h);
      cg.setTolerance(1e-10);
      if (cg_guess.size() != rhs.size()) cg_guess = VecX::Zero(rhs.size());
      VecX d = cg.solveWithGuess(rhs, cg_guess);
      cg_guess = d;
      return d;
    }
    // Levenberg shifts where the (projected) matrix is still not positive definite (free particles in a
    // quasi-static step, or round-off).
    double shift = 0.0;
    const double diag = h.diagonal().cwiseAbs().maxCoeff();
    for (int attempt = 0; attempt < 12; ++attempt) {
      if (cholesky.factorize(h)) return cholesky.solve(rhs);
      const double next = shift == 0.0 ? 1e-10 * diag : 10.0 * shift;
      for (int i = 0; i < h.rows(); ++i) h.coeffRef(i, i) += next - shift;
      shift = next;
    }
    throw SolverFailure("the Newton matrix of the time step is not positive definite even with a shift");
  }

  StepReport implicit_step(double dt, bool quasi_static) {
    x_n = x;
    VecX x_hat = x + dt * v, y = x_hat;
    apply_prescribed(y);
    apply_prescribed(x_hat);
    if (quasi_static || !std::isfinite(model().energy(y))) {
      y = x;
      apply_prescribed(y);
    }
    const double w = quasi_static ? 0.0 : 1.0 / (dt * dt);
    StepReport r = newton(y, x_hat, w, quasi_static ? 0.0 : dt);
    v = quasi_static ? VecX::Zero(x.size()) : VecX((y - x) / dt);
    x = y;
    gradient_valid = false;
    return r;
  }

  void setup_local_global() {
    for (const auto& b : model().blocks()) {
      if (b->name() == "orientation-guard") continue;
      const auto* s = dynamic_cast<const springs::SpringBlock*>(b.get());
      if (!s)
        throw InvalidArgument("local-global needs a spring-only model; this one has a '" + std::string(b->name()) +
                              "' block (use implicit-euler)");
      const Eigen::Index off = springs.k.size();
      springs.pairs.insert(springs.pairs.end(), s->pairs().begin(), s->pairs().end());
      springs.k.conservativeResize(off + s->stiffness().size());
      springs.k.tail(s->stiffness().size()) = s->stiffness();
      springs.l0.conservativeResize(off + s->rest_length().size());
      springs.l0.tail(s->rest_length().size()) = s->rest_length();
    }
  }

  // Local step of Liu et al. 2013: each spring's best direction d_s = l0_s (y_i - y_j) / |y_i - y_j|,
  // accumulated as J d (k_s d_s added at i, subtracted at j). Fixed-size vectors: no allocation per spring.
  template <int D>
  void local_step(const VecX& y, VecX& jd) const {
    jd.setZero();
    for (size_t s = 0; s < springs.pairs.size(); ++s) {
      const int i = springs.pairs[s][0], j = springs.pairs[s][1];
      const Eigen::Matrix<double, D, 1> dij = y.segment<D>(D * i) - y.segment<D>(D * j);
      const double len = dij.norm();
      if (len == 0.0) continue;
      const Eigen::Matrix<double, D, 1> ds =
          (springs.k(static_cast<Eigen::Index>(s)) * springs.l0(static_cast<Eigen::Index>(s)) / len) * dij;
      jd.segment<D>(D * i) += ds;
      jd.segment<D>(D * j) -= ds;
    }
  }

  StepReport local_global_step(double dt) {
    const int d = model().dim();
    const Eigen::Index nd = x.size();
    if (dt != lg_dt) {
      std::vector<Triplet> t;
      for (size_t s = 0; s < springs.pairs.size(); ++s) {
        const int i = springs.pairs[s][0], j = springs.pairs[s][1];
        const double k = springs.k(static_cast<Eigen::Index>(s));
        for (int a = 0; a < d; ++a) {
          t.emplace_back(d * i + a, d * i + a, k);
          t.emplace_back(d * j + a, d * j + a, k);
          t.emplace_back(d * i + a, d * j + a, -k);
          t.emplace_back(d * j + a, d * i + a, -k);
        }
      }
      for (Eigen::Index i = 0; i < nd; ++i) t.emplace_back(i, i, dyn.mass(i) / (dt * dt));
      lg_a.resize(nd, nd);
      lg_a.setFromTriplets(t.begin(), t.end());
      if (damping.rows() > 0) lg_a += damping / dt;
      if (!lg_factor.factorize(free.restrict(lg_a)))
        throw SolverFailure("the local-global system matrix is not positive definite");
      lg_dt = dt;
    }
    x_n = x;
    VecX x_hat = x + dt * v, y = x_hat;
    apply_prescribed(y);
    VecX fixed_part = VecX::Zero(nd);
    for (size_t i = 0; i < problem.fixed_dofs.size(); ++i)
      if (problem.fixed_dofs[i]) fixed_part(static_cast<Eigen::Index>(i)) = y(static_cast<Eigen::Index>(i));
    VecX rhs0 = dyn.mass.cwiseProduct(x_hat) / (dt * dt) + f_total - lg_a * fixed_part;
    if (damping.rows() > 0) rhs0 += damping * x_n / dt;
    VecX jd(nd);
    for (int it = 0; it < opt.local_global_iterations; ++it) {
      if (d == 3)
        local_step<3>(y, jd);
      else
        local_step<2>(y, jd);
      const VecX yf = lg_factor.solve(free.restrict(VecX(rhs0 + jd)));  // global step
      for (int i = 0; i < free.size(); ++i) y(free.free[static_cast<size_t>(i)]) = yf(i);
    }
    StepReport r;
    r.iterations = opt.local_global_iterations;
    r.residual = free.restrict(objective_gradient(y, x_hat, 1.0 / (dt * dt), dt)).norm();
    v = (y - x) / dt;
    x = y;
    gradient_valid = false;
    return r;
  }
};

Simulator::Simulator(model::Problem problem, Dynamics dynamics, SimulatorOptions options)
    : m(std::make_unique<Impl>(std::move(problem), std::move(dynamics), options)) {
  const int nd = m->model().dof_count();
  if (m->problem.fixed_dofs.size() != static_cast<size_t>(nd)) m->problem.fixed_dofs.assign(nd, 0);
  if (m->dyn.mass.size() != nd) throw InvalidArgument("Simulator: the mass vector needs one entry per DOF");
  for (int i : m->free.free)
    if (!(m->dyn.mass(i) > 0.0)) throw InvalidArgument("Simulator: free DOF " + std::to_string(i) + " has no mass");
  if (m->dyn.gravity.size() != 0 && m->dyn.gravity.size() != m->model().dim())
    throw InvalidArgument("Simulator: gravity needs one component per axis");
  if (m->dyn.mass_damping < 0.0 || m->dyn.stiffness_damping < 0.0)
    throw InvalidArgument("Simulator: Rayleigh damping coefficients must be >= 0");
  if (m->dyn.mass_damping > 0.0 || m->dyn.stiffness_damping > 0.0) {
    m->damping = m->dyn.stiffness_damping * m->rest_stiffness();
    if (m->damping.rows() == 0) m->damping.resize(nd, nd);
    for (int i = 0; i < nd; ++i) m->damping.coeffRef(i, i) += m->dyn.mass_damping * m->dyn.mass(i);
  }
  if (options.integrator == Integrator::kLocalGlobal) m->setup_local_global();
  m->base_fixed = m->problem.fixed_dofs;
  m->x = model::initial_positions(m->problem);
  m->v = VecX::Zero(nd);
}

Simulator::~Simulator() = default;
Simulator::Simulator(Simulator&&) noexcept = default;
Simulator& Simulator::operator=(Simulator&&) noexcept = default;

StepReport Simulator::step(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt)) throw InvalidArgument("the time step must be a positive number");
  m->update_loads();
  m->update_probe_targets();
  StepReport r;
  switch (m->opt.integrator) {
    case Integrator::kSymplecticEuler: r = m->explicit_step(dt, false); break;
    case Integrator::kVelocityVerlet: r = m->explicit_step(dt, true); break;
    case Integrator::kImplicitEuler: r = m->implicit_step(dt, false); break;
    case Integrator::kQuasiStatic: r = m->implicit_step(dt, true); break;
    case Integrator::kLocalGlobal: r = m->local_global_step(dt); break;
  }
  m->time_s += dt;
  r.probe_force = m->probe_force();
  return r;
}

double Simulator::time() const { return m->time_s; }
const VecX& Simulator::positions() const { return m->x; }
const VecX& Simulator::velocities() const { return m->v; }
void Simulator::set_state(const VecX& positions, const VecX& velocities) {
  if (positions.size() != m->x.size() || velocities.size() != m->v.size())
    throw InvalidArgument("Simulator::set_state: sizes differ from the model's DOF count");
  m->x = positions;
  m->v = velocities;
  m->gradient_valid = false;
}
model::Problem& Simulator::problem() { return m->problem; }

void Simulator::set_probe(const Probe& probe) {
  const int d = m->model().dim(), n = m->model().node_count();
  for (int node : probe.nodes)
    if (node < 0 || node >= n) throw InvalidArgument("probe node " + std::to_string(node) + " is not in the model");
  if (!probe.nodes.empty() &&
      ((probe.drive_position && probe.offset.size() != d) || (!probe.drive_position && probe.force.size() != d)))
    throw InvalidArgument("the probe's offset or force needs one component per axis");
  const bool same = probe.nodes == m->probe.nodes && probe.drive_position == m->probe.drive_position;
  if (!same) {
    m->problem.fixed_dofs = m->base_fixed;
    m->grab_positions.resize(d * static_cast<Eigen::Index>(probe.nodes.size()));
    for (size_t k = 0; k < probe.nodes.size(); ++k) {
      m->grab_positions.segment(d * static_cast<Eigen::Index>(k), d) = m->x.segment(d * probe.nodes[k], d);
      if (probe.drive_position)
        for (int a = 0; a < d; ++a) m->problem.fixed_dofs[static_cast<size_t>(d * probe.nodes[k] + a)] = 1;
    }
    m->refix();
  }
  m->probe = probe;
}
const Dynamics& Simulator::dynamics() const { return m->dyn; }
double Simulator::kinetic_energy() const { return 0.5 * m->v.cwiseAbs2().dot(m->dyn.mass); }
double Simulator::potential_energy() const {
  m->update_loads();
  return m->model().energy(m->x) - m->f_total.dot(m->x - m->model().rest_positions());
}
VecX Simulator::momentum() const {
  const int d = m->model().dim();
  VecX p = VecX::Zero(d);
  for (Eigen::Index i = 0; i < m->x.size(); ++i) p(i % d) += m->dyn.mass(i) * m->v(i);
  return p;
}
double Simulator::stable_time_step() const { return m->stable_dt(); }

}  // namespace hooke::solve
