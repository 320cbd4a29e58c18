#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/model/hessian_assembly.hpp>
#include <hooke/solve/simulator.hpp>
#include <hooke/solve/sparse_cholesky.hpp>
#include <limits>
#include <string>

namespace hooke::solve {
namespace {

constexpr std::string_view kNames[] = {"symplectic-euler", "velocity-verlet", "implicit-euler",
                                       "local-global",     "quasi-static",    "implicit-euler-linearised"};

// Matrix-vector products with at least this many rows run on all threads (measured on two: 34 263 rows 1.6x faster; 3
// 267 rows no faster, the barrier costs what the split saves).
constexpr int kParallelRows = 10000;

// out = A z for a symmetric matrix stored whole in compressed columns (allocation-free): by symmetry column c
// holds row c, so each entry of out is one gathered dot product (no scattered writes).
// Rows are independent, so large products run on all threads (a plain loop below the threshold: an OpenMP region
// with if(false) still allocates in libgomp, and step() must not).
void multiply(const SparseMatrix& a, const VecX& z, VecX& out) {
  const int* start = a.outerIndexPtr();
  const int* rows = a.innerIndexPtr();
  const double* values = a.valuePtr();
  const double* in = z.data();
  double* result = out.data();
  const int n = static_cast<int>(a.outerSize());
  auto row = [&](int c) {
    double sum = 0.0;
    for (int q = start[c]; q < start[c + 1]; ++q) sum += values[q] * in[rows[q]];
    result[c] = sum;
  };
  if (n >= kParallelRows) {
#pragma omp parallel for schedule(static)
    for (int c = 0; c < n; ++c) row(c);
  } else {
    for (int c = 0; c < n; ++c) row(c);
  }
}

// out += A z for A acting on r interleaved components per row (a per-node matrix on flat node-major vectors).
void add_product(const SparseMatrix& a, const VecX& z, int r, VecX& out) {
  for (int c = 0; c < a.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(a, c); it; ++it)
      for (int k = 0; k < r; ++k) out(r * it.row() + k) += it.value() * z(r * c + k);
}

// Replaces the rows and columns of fixed unknowns by those of the identity; unknown u is fixed when
// fixed[stride * u] (stride = components per unknown of the fixed-DOF flags).
void constrain(SparseMatrix& a, const std::vector<char>& fixed, int stride) {
  for (int c = 0; c < a.outerSize(); ++c) {
    const bool column_fixed = fixed[static_cast<size_t>(stride * c)];
    for (SparseMatrix::InnerIterator it(a, c); it; ++it)
      if (column_fixed || fixed[static_cast<size_t>(stride * it.row())]) it.valueRef() = it.row() == c ? 1.0 : 0.0;
  }
}

}  // namespace

Integrator integrator_from_name(std::string_view name) {
  for (size_t i = 0; i < std::size(kNames); ++i)
    if (kNames[i] == name) return static_cast<Integrator>(i);
  throw InvalidArgument("unknown integrator '" + std::string(name) +
                        "' (use symplectic-euler, velocity-verlet, implicit-euler, implicit-euler-linearised, "
                        "local-global, quasi-static)");
}

std::string_view integrator_name(Integrator integrator) { return kNames[static_cast<size_t>(integrator)]; }

NewtonLinearSolver newton_linear_solver_from_name(std::string_view name) {
  if (name == "cholesky") return NewtonLinearSolver::kCholesky;
  if (name == "cg") return NewtonLinearSolver::kConjugateGradient;
  throw InvalidArgument("unknown linear solver '" + std::string(name) + "' (use cholesky or cg)");
}

GlobalSolve global_solve_from_name(std::string_view name) {
  if (name == "direct") return GlobalSolve::kDirect;
  if (name == "chebyshev") return GlobalSolve::kChebyshev;
  throw InvalidArgument("unknown global solve '" + std::string(name) + "' (use direct or chebyshev)");
}

struct Simulator::Impl {
  model::Problem problem;
  Dynamics dyn;
  SimulatorOptions opt;
  Eigen::Index nd = 0;
  // State and work vectors, sized once (step() allocates nothing after the first call).
  VecX x, v, x_n, x_hat, y, trial, grad, grad_trial, delta, rhs, f_total, acc, damp_in, damp_out;
  bool gradient_valid = false;  // grad holds dE/dx at x (explicit steps)
  double time_s = 0.0;
  std::unique_ptr<model::HessianAssembly> assembly;  // fixed-pattern Hessian (implicit steps, K0)
  SparseMatrix k0;                                   // Hessian at rest on the assembly's pattern
  SparseCholesky cholesky;
  bool have_factor = false;  // `cholesky` holds a factorisation of an earlier Newton matrix
  double factor_w = -1.0, factor_dt = -1.0;
  VecX cg_r, cg_z, cg_p, cg_q, cg_blocks;
  long cg_iterations = 0;             // since the step began
  std::vector<int> cg_block_offsets;  // per DOF and block column: offset in the Newton matrix's values, or -1
  // Local-global only: the spring blocks. Liu et al. 2013 write the springs' part of the incremental potential
  // as a minimum over directions d_s, |d_s| = l0_s, of sum_s k_s/2 |x_i - x_j - d_s|^2, which makes the global
  // step one constant linear system.
  std::vector<const model::CentralSprings*> spring_blocks;
  std::vector<const model::TermBlock*> spring_terms;  // the same blocks, for their gradients
  int lg_components = 1;     // 1: the system acts on DOFs; dim: one per-node matrix for all axes (Kronecker)
  SparseMatrix lg_a;         // M/dt^2 + D/dt + L, unconstrained
  SparseCholesky lg_factor;  // of lg_a with the fixed unknowns' rows and columns replaced by the identity's
  double lg_dt = -1.0;
  VecX lg_rhs0, lg_jd;
  VecX lg_inv_diag, lg_previous;   // chebyshev: 1 / diag(A) per DOF (0 on fixed DOFs), the last update
  double lg_lo = 0.0, lg_b = 2.0;  // chebyshev: the interval [lo, b] of D^-1 H it is tuned to
  double lg_a_min = 0.0;           // chebyshev: the lowest a that keeps the time step stable
  Probe probe;
  VecX grab_positions;           // positions of the probe nodes' DOFs when grabbed
  std::vector<char> base_fixed;  // fixed DOFs of the problem without the probe
  double stable_dt_cache = -1.0;

  Impl(model::Problem p, Dynamics d, SimulatorOptions o)
      : problem(std::move(p)), dyn(std::move(d)), opt(o), nd(problem.model->dof_count()) {
    for (VecX* w :
         {&x, &v, &x_n, &x_hat, &y, &trial, &grad, &grad_trial, &delta, &rhs, &f_total, &acc, &damp_in, &damp_out})
      w->setZero(nd);
  }

  const model::Model& model() const { return *problem.model; }
  bool fixed(Eigen::Index i) const { return problem.fixed_dofs[static_cast<size_t>(i)] != 0; }
  bool damped() const { return dyn.mass_damping > 0.0 || dyn.stiffness_damping > 0.0; }

  // After the fixed set changed: factorisations are redone on their next use (the patterns stay).
  void refix() {
    lg_dt = -1.0;
    have_factor = false;
    cg_r.resize(0);
    stable_dt_cache = -1.0;
  }

  model::HessianAssembly& hessian_assembly() {
    if (!assembly) assembly = std::make_unique<model::HessianAssembly>(model());
    return *assembly;
  }

  const SparseMatrix& rest_stiffness() {
    if (k0.rows() == 0) {
      hessian_assembly().assemble(model().rest_positions(), false);
      k0 = assembly->matrix();
    }
    return k0;
  }

  // out = D z = alpha M z + beta K0 z.
  void damping_product(const VecX& z, VecX& out) {
    if (dyn.stiffness_damping > 0.0) {
      multiply(rest_stiffness(), z, out);
      out *= dyn.stiffness_damping;
    } else {
      out.setZero();
    }
    if (dyn.mass_damping > 0.0) out += dyn.mass_damping * dyn.mass.cwiseProduct(z);
  }

  // Positions of the fixed DOFs now (prescribed, else rest).
  void apply_prescribed(VecX& z) const {
    const bool given = problem.prescribed_positions.size() == z.size();
    for (Eigen::Index i = 0; i < nd; ++i)
      if (fixed(i)) z(i) = given ? problem.prescribed_positions(i) : model().rest_positions()(i);
  }

  void update_loads() {
    if (problem.external_force.size() == nd)
      f_total = problem.external_force;
    else
      f_total.setZero();
    const int d = model().dim();
    if (dyn.gravity.size() == d)
      for (Eigen::Index i = 0; i < nd; ++i) f_total(i) += dyn.mass(i) * dyn.gravity(i % d);
    if (!probe.nodes.empty() && !probe.drive_position)
      for (int node : probe.nodes)
        f_total.segment(d * node, d) += probe.force / static_cast<double>(probe.nodes.size());
  }

  // A driving probe's nodes are fixed DOFs: their targets are grab position + offset.
  void update_probe_targets() {
    if (probe.nodes.empty() || !probe.drive_position) return;
    const int d = model().dim();
    if (problem.prescribed_positions.size() != nd) problem.prescribed_positions = model().rest_positions();
    for (size_t k = 0; k < probe.nodes.size(); ++k)
      problem.prescribed_positions.segment(d * probe.nodes[k], d) =
          grab_positions.segment(d * static_cast<Eigen::Index>(k), d) + probe.offset;
  }

  void add_probe_force(StepReport& r) {
    const int d = model().dim();
    r.probe_force.setZero(d);
    if (probe.nodes.empty()) return;
    if (!probe.drive_position) {
      r.probe_force = -probe.force;
      return;
    }
    model().gradient(x, grad);  // at the new x: also the next explicit step's gradient
    gradient_valid = true;
    for (int node : probe.nodes) r.probe_force -= grad.segment(d * node, d) - f_total.segment(d * node, d);
  }

  // acc = M^-1 (f - dE/dx(x) - D w) on the free DOFs, 0 on the fixed ones.
  void acceleration(const VecX& w) {
    if (!gradient_valid) {
      model().gradient(x, grad);
      gradient_valid = true;
    }
    acc = f_total - grad;
    if (damped()) {
      damping_product(w, damp_out);
      acc -= damp_out;
    }
    for (Eigen::Index i = 0; i < nd; ++i) acc(i) = fixed(i) ? 0.0 : acc(i) / dyn.mass(i);
  }

  StepReport explicit_step(double dt, bool verlet) {
    StepReport r;
    r.beyond_stable_dt = dt > stable_dt();
    x_hat = x;
    apply_prescribed(x_hat);  // targets of the fixed DOFs
    acceleration(v);
    v += (verlet ? 0.5 : 1.0) * dt * acc;  // (half) kick
    for (Eigen::Index i = 0; i < nd; ++i)  // drift; fixed DOFs move to their targets
      if (fixed(i)) {
        v(i) = (x_hat(i) - x(i)) / dt;
        x(i) = x_hat(i);
      } else {
        x(i) += dt * v(i);
      }
    gradient_valid = false;
    if (verlet) {
      acceleration(v);
      v += 0.5 * dt * acc;
    }
    return r;
  }

  double stable_dt() {
    if (stable_dt_cache >= 0.0) return stable_dt_cache;
    const SparseMatrix& k = rest_stiffness();
    // Power iteration on M^-1/2 K M^-1/2 (symmetric, same spectrum as M^-1 K) restricted to the free DOFs.
    VecX inv_sqrt_m = VecX::Zero(nd), z = VecX::Zero(nd), kz(nd);
    for (Eigen::Index i = 0; i < nd; ++i)
      if (!fixed(i)) {
        inv_sqrt_m(i) = 1.0 / std::sqrt(dyn.mass(i));
        z(i) = 1.0 + 0.1 * std::sin(1.0 + static_cast<double>(i));  // break symmetries
      }
    double lambda = 0.0;
    for (int it = 0; it < 200 && z.norm() > 0.0; ++it) {
      z.normalize();
      multiply(k, inv_sqrt_m.cwiseProduct(z), kz);
      const VecX next = inv_sqrt_m.cwiseProduct(kz);
      lambda = z.dot(next);
      z = next;
    }
    if (!(lambda > 0.0)) return stable_dt_cache = std::numeric_limits<double>::infinity();
    // Central differences with Rayleigh damping of ratio zeta = (alpha / omega + beta omega) / 2 at the highest
    // frequency are stable for omega dt <= 2 (sqrt(1 + zeta^2) - zeta) (e.g. Belytschko et al., Nonlinear
    // Finite Elements, Sec. 6.2); zeta = 0 gives 2 / omega.
    const double omega = std::sqrt(lambda);
    const double zeta = 0.5 * (dyn.mass_damping / omega + dyn.stiffness_damping * omega);
    return stable_dt_cache = 2.0 / omega * (std::sqrt(1.0 + zeta * zeta) - zeta);
  }

  // Incremental potential of implicit Euler (w = 1/dt^2) or the static potential (w = 0) at z.
  double objective(const VecX& z, double w, double dt) {
    const double e = model().energy(z);
    if (!std::isfinite(e)) return e;
    double phi = e - f_total.dot(z - model().rest_positions());
    if (w > 0.0) phi += 0.5 * w * (z - x_hat).cwiseAbs2().dot(dyn.mass);
    if (damped() && dt > 0.0) {
      damp_in = z - x_n;
      damping_product(damp_in, damp_out);
      phi += 0.5 / dt * damp_in.dot(damp_out);
    }
    return phi;
  }

  // out = d objective / dz, zero on the fixed DOFs.
  void objective_gradient(const VecX& z, double w, double dt, VecX& out) {
    model().gradient(z, out);
    out -= f_total;
    if (w > 0.0) out += w * dyn.mass.cwiseProduct(z - x_hat);
    if (damped() && dt > 0.0) {
      damp_in = z - x_n;
      damping_product(damp_in, damp_out);
      out += damp_out / dt;
    }
    for (Eigen::Index i = 0; i < nd; ++i)
      if (fixed(i)) out(i) = 0.0;
  }

  // The Newton matrix H + w M + D/dt at z, fixed DOFs replaced by the identity, in the assembly's matrix; with
  // `project`, every element Hessian projected to PSD first.
  SparseMatrix& newton_matrix(const VecX& z, double w, double dt, bool project) {
    model::HessianAssembly& a = hessian_assembly();
    if (damped() && dt > 0.0 && dyn.stiffness_damping > 0.0) rest_stiffness();  // before `a` is overwritten
    a.assemble(z, project);
    double* values = a.matrix().valuePtr();
    if (damped() && dt > 0.0 && dyn.stiffness_damping > 0.0) {
      const double* k = k0.valuePtr();
      for (Eigen::Index q = 0; q < a.matrix().nonZeros(); ++q) values[q] += dyn.stiffness_damping / dt * k[q];
    }
    const double mass_factor = w + (dt > 0.0 ? dyn.mass_damping / dt : 0.0);
    for (Eigen::Index i = 0; i < nd; ++i) values[a.diagonal()[static_cast<size_t>(i)]] += mass_factor * dyn.mass(i);
    constrain(a.matrix(), problem.fixed_dofs, 1);
    return a.matrix();
  }

  // The Newton direction at z into `delta`: from the exact Newton matrix unless options.project_psd, and from the
  // PSD-projected one where the exact one is not positive definite (compressed springs in a quasi-static step, a
  // large dt); cg to relative residual `cg_tolerance`, warm-started from the last direction.
  void newton_direction(const VecX& z, double w, double dt, double cg_tolerance) {
    const bool cg = opt.linear_solver == NewtonLinearSolver::kConjugateGradient;
    if (cg) {
      if (conjugate_gradient(newton_matrix(z, w, dt, opt.project_psd), cg_tolerance) || opt.project_psd) return;
      delta.setZero();
      conjugate_gradient(newton_matrix(z, w, dt, true), cg_tolerance);
      return;
    }
    if (opt.project_psd || !cholesky.factorize(newton_matrix(z, w, dt, false)))
      factorize(newton_matrix(z, w, dt, true));
    delta = -grad;
    cholesky.solve_in_place(delta.data(), 1);
  }

  // Factorises h, with Levenberg shifts on the free diagonal where the (projected) matrix is still not positive
  // definite (free particles in a quasi-static step, round-off).
  void factorize(SparseMatrix& h) {
    double shift = 0.0;
    const double diag = h.diagonal().cwiseAbs().maxCoeff();
    const std::vector<int>& d = assembly->diagonal();
    for (int attempt = 0; attempt < 12; ++attempt) {
      if (cholesky.factorize(h)) return;
      const double next = shift == 0.0 ? 1e-10 * diag : 10.0 * shift;
      for (Eigen::Index i = 0; i < nd; ++i)
        if (!fixed(i)) h.valuePtr()[d[static_cast<size_t>(i)]] += next - shift;
      shift = next;
    }
    throw SolverFailure("the Newton matrix of the time step is not positive definite even with a shift");
  }

  // Node-block Jacobi preconditioner: the inverse of each node's dim x dim diagonal block of h (identity rows for
  // fixed DOFs). Elasticity couples a node's axes strongly, so this takes about half the CG iterations of the
  // scalar diagonal on the spring cylinders. cg_blocks holds the inverses, dim^2 per node, row-major.
  void block_preconditioner(const SparseMatrix& h) {
    const int d = model().dim();
    const Eigen::Index n = nd / d;
    if (cg_block_offsets.empty()) {  // where each block entry sits in h's value array (the pattern is fixed)
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

  void precondition(const VecX& r, VecX& z) const {
    const int d = model().dim();
    for (Eigen::Index i = 0; i < nd / d; ++i)
      for (int a = 0; a < d; ++a) {
        double sum = 0.0;
        for (int c = 0; c < d; ++c) sum += cg_blocks(d * d * i + d * a + c) * r(d * i + c);
        z(d * i + a) = sum;
      }
  }

  // Preconditioned conjugate gradients on h delta = -grad to |residual| <= tolerance |grad|, warm-started from the
  // last solution. Returns false where h shows a direction of non-positive curvature (not positive definite).
  bool conjugate_gradient(const SparseMatrix& h, double tolerance) {
    if (cg_r.size() != nd) {
      for (VecX* w : {&cg_r, &cg_z, &cg_p, &cg_q}) w->setZero(nd);
      delta.setZero();
    }
    block_preconditioner(h);
    multiply(h, delta, cg_q);
    cg_r = -grad - cg_q;
    const double target = tolerance * grad.norm();
    precondition(cg_r, cg_z);
    cg_p = cg_z;
    double rz = cg_r.dot(cg_z);
    for (Eigen::Index k = 0; k < 4 * nd && cg_r.norm() > target; ++k) {
      ++cg_iterations;
      multiply(h, cg_p, cg_q);
      const double curvature = cg_p.dot(cg_q);
      if (!(curvature > 0.0)) return false;
      const double alpha = rz / curvature;
      delta += alpha * cg_p;
      cg_r -= alpha * cg_q;
      precondition(cg_r, cg_z);
      const double rz_next = cg_r.dot(cg_z);
      cg_p = cg_z + (rz_next / rz) * cg_p;
      rz = rz_next;
    }
    return true;
  }

  // Newton's method with backtracking line search on the objective; y holds the start and the result.
  StepReport newton(double w, double dt) {
    StepReport r;
    objective_gradient(y, w, dt, grad);
    double load = 0.0;
    for (Eigen::Index i = 0; i < nd; ++i)
      if (!fixed(i)) load += f_total(i) * f_total(i);
    const double scale = std::sqrt(load) + grad.norm() + 1e-30;
    const bool potential = model().conservative();
    double phi = potential ? objective(y, w, dt) : 0.0;
    double previous = std::numeric_limits<double>::infinity();
    double eta = 0.1, last_residual = 0.0;  // cg: forcing term and the residual it was chosen at
    int it = 0;
    for (; it < opt.max_newton_iterations; ++it) {
      objective_gradient(y, w, dt, grad);
      r.residual = grad.norm();
      r.iterations = it;
      if (r.residual <= opt.newton_tolerance * scale) return r;
      // Modified Newton: keep the last factorisation (of an earlier iterate, possibly an earlier step) while it
      // still reduces the residual at least fourfold per iteration; refactorise when it does not, when it
      // gives no descent, or when its line search fails.
      const bool cg = opt.linear_solver == NewtonLinearSolver::kConjugateGradient;
      const bool reuse = !cg && opt.reuse_factorization && have_factor && factor_w == w && factor_dt == dt &&
                         r.residual <= 0.25 * previous;
      if (cg) {
        // Inexact Newton (Eisenstat & Walker 1996, choice 2): the CG tolerance follows the residual's decrease,
        // loose far from the solution, down to cg_tolerance near it; tightened when the step is no descent.
        if (it > 0)
          eta = std::clamp(0.9 * (r.residual / last_residual) * (r.residual / last_residual), opt.cg_tolerance, 0.1);
        last_residual = r.residual;
        newton_direction(y, w, dt, eta);
        if (!(grad.dot(delta) < 0.0) && eta > opt.cg_tolerance) newton_direction(y, w, dt, opt.cg_tolerance);
      } else if (reuse) {
        delta = -grad;
        cholesky.solve_in_place(delta.data(), 1);
      } else {
        newton_direction(y, w, dt, 0.0);
        have_factor = true;
        factor_w = w;
        factor_dt = dt;
      }
      previous = reuse ? r.residual : std::numeric_limits<double>::infinity();
      double alpha = 1.0;
      const double slope = grad.dot(delta);
      if (potential && !(slope < 0.0)) {
        if (!reuse) break;
        have_factor = false;
        continue;
      }
      bool accepted = false;
      for (int ls = 0; ls < 40; ++ls) {
        trial = y + alpha * delta;
        if (potential) {
          const double p = objective(trial, w, dt);
          if (std::isfinite(p) && p <= phi + 1e-4 * alpha * slope) {
            phi = p;
            accepted = true;
            break;
          }
        } else {
          // No potential (the surface model's blended anchors): backtrack on the residual norm.
          objective_gradient(trial, w, dt, grad_trial);
          const double rt = grad_trial.norm();
          if (std::isfinite(rt) && rt <= (1.0 - 1e-4 * alpha) * r.residual) {
            accepted = true;
            break;
          }
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
        objective_gradient(y, w, dt, grad);
        r.residual = grad.norm();
        return r;
      }
    }
    objective_gradient(y, w, dt, grad);
    r.residual = grad.norm();
    r.converged = r.residual <= opt.newton_tolerance * scale;
    r.iterations = it;  // the limit, or where the line search found no descent
    return r;
  }

  StepReport implicit_step(double dt, bool quasi_static) {
    x_n = x;
    x_hat = x + dt * v;
    apply_prescribed(x_hat);
    y = x_hat;
    if (quasi_static || !std::isfinite(model().energy(y))) {
      y = x;
      apply_prescribed(y);
    }
    const double w = quasi_static ? 0.0 : 1.0 / (dt * dt);
    StepReport r = newton(w, quasi_static ? 0.0 : dt);
    if (quasi_static)
      v.setZero();
    else
      v = (y - x) / dt;
    x = y;
    gradient_valid = false;
    return r;
  }

  // Baraff & Witkin 1998: one Newton iteration of the incremental potential from y = x_n (fixed DOFs at their
  // targets), i.e. (M + dt D + dt^2 K(x_n)) dv = dt (f - grad E(x_n) - D v_n - dt K(x_n) v_n), with no line search.
  StepReport linearised_step(double dt) {
    x_n = x;
    x_hat = x + dt * v;
    apply_prescribed(x_hat);
    y = x;
    apply_prescribed(y);
    const double w = 1.0 / (dt * dt);
    objective_gradient(y, w, dt, grad);
    newton_direction(y, w, dt, opt.cg_tolerance);
    have_factor = false;  // the factor belongs to this step's matrix only
    y += delta;
    StepReport r;
    r.iterations = 1;
    objective_gradient(y, w, dt, grad);
    r.residual = grad.norm();  // what the one iteration leaves of the implicit step's equations
    v = (y - x) / dt;
    x = y;
    gradient_valid = false;
    return r;
  }

  void setup_local_global() {
    for (const auto& b : model().blocks()) {
      if (!b->has_forces()) continue;  // admissibility only (the orientation guard): checked by energy()
      const model::CentralSprings* s = b->central_springs();
      if (!s)
        throw InvalidArgument("local-global needs a model of central springs only; this one has a '" +
                              std::string(b->name()) + "' block (use implicit-euler)");
      spring_blocks.push_back(s);
      spring_terms.push_back(b.get());
    }
    lg_rhs0.setZero(nd);
    lg_jd.setZero(nd);
  }

  // The global matrix M/dt^2 + D/dt + sum_s k_s (e_i - e_j)(e_i - e_j)^T. Without stiffness damping, with equal
  // masses on a node's axes and nodes fixed on all axes or none, it is (per-node matrix) x I_dim: one factor of
  // a #nodes-square matrix then serves every axis (Kronecker form).
  void setup_global_matrix(double dt) {
    const int d = model().dim();
    bool kronecker = dyn.stiffness_damping == 0.0;
    for (Eigen::Index i = 0; i < nd && kronecker; ++i)
      kronecker = dyn.mass(i) == dyn.mass(i - i % d) && fixed(i) == fixed(i - i % d);
    lg_components = kronecker ? d : 1;
    const int r = lg_components, n = static_cast<int>(nd) / r, axes = d / r;
    std::vector<Triplet> t;
    for (const model::CentralSprings* b : spring_blocks)
      for (size_t s = 0; s < b->pairs().size(); ++s) {
        const int i = b->pairs()[s][0], j = b->pairs()[s][1];
        const double k = b->stiffness()(static_cast<Eigen::Index>(s));
        for (int a = 0; a < axes; ++a) {
          t.emplace_back(axes * i + a, axes * i + a, k);
          t.emplace_back(axes * j + a, axes * j + a, k);
          t.emplace_back(axes * i + a, axes * j + a, -k);
          t.emplace_back(axes * j + a, axes * i + a, -k);
        }
      }
    for (int u = 0; u < n; ++u) {
      const double m = dyn.mass(r * u);
      t.emplace_back(u, u, m / (dt * dt) + dyn.mass_damping * m / dt);
    }
    lg_a.resize(n, n);
    lg_a.setFromTriplets(t.begin(), t.end());
    if (dyn.stiffness_damping > 0.0) lg_a += (dyn.stiffness_damping / dt) * rest_stiffness();
    lg_dt = dt;
    if (opt.global_solve == GlobalSolve::kChebyshev) {
      setup_chebyshev(dt);
      return;
    }
    SparseMatrix constrained = lg_a;
    constrain(constrained, problem.fixed_dofs, r);
    if (!lg_factor.factorize(constrained))
      throw SolverFailure("the local-global system matrix is not positive definite");
  }

  // The Chebyshev global step (docs/simulation.md). Each iteration refreshes the local step's directions, so the
  // error of the step's solution y* contracts, near it, like a Jacobi-preconditioned Richardson iteration on the
  // true Newton matrix H = M/dt^2 + D/dt + K (the directions' derivative turns L into the springs' stiffness):
  // after k iterations it is P_k(D^-1 H) times the initial error, P_k the Chebyshev polynomial of the interval
  // [a, b] that holds the spectrum of D^-1 H, |P_k| <= 1 / T_k((b + a) / (b - a)) on it (D = diag A).
  // - b = 2: D^-1 H <= D^-1 A <= 2 (H <= A for springs at or beyond their rest length; Gershgorin on the diagonally
  //   dominant A).
  // - a: the smallest Ritz value of D^-1/2 H D^-1/2 at rest (Lanczos over the free DOFs), raised where needed for
  //   the stability of the time step: a step that ends at y* + P (x_hat - y*) maps a mode (x, v) with the
  //   amplification matrix [[g, g dt], [(g - 1) / dt, g]], g = s + P (1 - s), s in (0, 1] (s = 1 for a mode without
  //   stiffness), whose eigenvalues g +- sqrt(g^2 - g) lie in the unit disc only for -1/3 <= g <= 1. P may
  //   therefore not dip below -1/3 on stiff modes (s -> 0): with few iterations the interval is cut from below
  //   until 1 / T_k((b + a) / (b - a)) <= 1/4. Modes below a then converge monotonically (0 < P < 1), more slowly.
  //   (The test with 10 iterations on the 1 089-node cylinder: the bound at 0.26 settles, at 0.46 it oscillates.)
  void setup_chebyshev(double dt) {
    const int r = lg_components;
    lg_inv_diag.setZero(nd);
    lg_previous.setZero(nd);
    for (Eigen::Index i = 0; i < nd; ++i)
      if (!fixed(i)) lg_inv_diag(i) = 1.0 / lg_a.coeff(i / r, i / r);
    lg_b = 2.0;
    const double k_it = opt.local_global_iterations;
    const double sigma_stable = std::cosh(std::acosh(4.0) / k_it);  // T_k(sigma_stable) = 4
    lg_a_min = lg_b * (sigma_stable - 1.0) / (sigma_stable + 1.0);
    if (!opt.chebyshev_acceleration) return;
    const SparseMatrix& k = rest_stiffness();
    const double k_scale = 1.0 + dyn.stiffness_damping / dt;
    VecX s = lg_inv_diag.cwiseSqrt(), m_scale = dyn.mass * (1.0 / (dt * dt) + dyn.mass_damping / dt);
    auto apply = [&](const VecX& z, VecX& out) {  // out = D^-1/2 H D^-1/2 z on the free DOFs
      const VecX sz = s.cwiseProduct(z);
      multiply(k, sz, out);
      out = s.cwiseProduct(k_scale * out + m_scale.cwiseProduct(sz));
    };
    const Eigen::Index free = (lg_inv_diag.array() > 0.0).count();
    const int steps = static_cast<int>(std::min<Eigen::Index>(80, free));
    if (steps == 0) return;
    VecX q = VecX::Zero(nd), q_prev = VecX::Zero(nd), w(nd);
    for (Eigen::Index i = 0; i < nd; ++i)
      if (lg_inv_diag(i) > 0.0) q(i) = 1.0 + 0.3 * std::sin(1.0 + 7.0 * static_cast<double>(i));
    q.normalize();
    VecX alpha = VecX::Zero(steps), beta = VecX::Zero(steps);
    int m = 0;
    for (; m < steps; ++m) {
      apply(q, w);
      alpha(m) = q.dot(w);
      w -= alpha(m) * q + (m > 0 ? beta(m - 1) : 0.0) * q_prev;
      beta(m) = w.norm();
      if (beta(m) <= 1e-12 * std::abs(alpha(m))) {
        ++m;
        break;
      }
      q_prev = q;
      q = w / beta(m);
    }
    Eigen::MatrixXd t = Eigen::MatrixXd::Zero(m, m);
    for (int i = 0; i < m; ++i) {
      t(i, i) = alpha(i);
      if (i + 1 < m) t(i, i + 1) = t(i + 1, i) = beta(i);
    }
    const VecX ritz = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(t, Eigen::EigenvaluesOnly).eigenvalues();
    lg_lo = std::clamp(ritz(0), lg_a_min, lg_b);
  }

  // Chebyshev iteration (e.g. Saad, Iterative Methods for Sparse Linear Systems, 2nd ed., Alg. 12.1) with the
  // Jacobi preconditioner on the step's nonlinear residual, restarted every step: theta = (b + a) / 2,
  // delta = (b - a) / 2; d_0 = D^-1 r_0 / theta; d_k = rho_k rho_{k-1} d_{k-1} + 2 rho_k / delta D^-1 r_k with
  // rho_0 = delta / theta, rho_k = 1 / (2 theta / delta - rho_{k-1}); y += d_k. The residual needs the local step's
  // J d(y) and the Laplacian's L y only as J d - L y = -dE_springs/dy, so each iteration is one spring-gradient
  // pass: r = rhs0 - M (1/dt^2 + alpha/dt) y - beta/dt K0 y - dE/dy. Without acceleration: y += D^-1 r (Jacobi).
  void chebyshev_iterations(double dt) {
    const double a = opt.chebyshev_acceleration ? lg_lo : lg_a_min;
    const double theta = 0.5 * (lg_b + a), half_width = 0.5 * (lg_b - a);
    const double m_factor = 1.0 / (dt * dt) + dyn.mass_damping / dt;
    double rho = half_width / theta;
    for (int it = 0; it < opt.local_global_iterations; ++it) {
      delta.setZero();
      for (const model::TermBlock* b : spring_terms) b->add_gradient(y, delta);
      if (dyn.stiffness_damping > 0.0) {
        multiply(k0, y, damp_out);
        delta += (dyn.stiffness_damping / dt) * damp_out;
      }
      const double rho_next = it == 0 ? rho : 1.0 / (2.0 * theta / half_width - rho);
      const double keep = it == 0 ? 0.0 : rho_next * rho, push = it == 0 ? 1.0 / theta : 2.0 * rho_next / half_width;
      for (Eigen::Index i = 0; i < nd; ++i) {
        const double z = (lg_rhs0(i) - m_factor * dyn.mass(i) * y(i) - delta(i)) * lg_inv_diag(i);  // 0 if fixed
        lg_previous(i) = opt.chebyshev_acceleration ? keep * lg_previous(i) + push * z : z;
        y(i) += lg_previous(i);
      }
      rho = rho_next;
    }
  }

  StepReport local_global_step(double dt) {
    if (dt != lg_dt) setup_global_matrix(dt);
    x_n = x;
    x_hat = x + dt * v;
    y = x_hat;
    apply_prescribed(y);
    // Right-hand side without the springs: M x_hat / dt^2 + f + D x_n / dt - A (fixed part of y).
    lg_rhs0 = dyn.mass.cwiseProduct(x_hat) / (dt * dt) + f_total;
    if (damped()) {
      damping_product(x_n, damp_out);
      lg_rhs0 += damp_out / dt;
    }
    if (opt.global_solve == GlobalSolve::kChebyshev) {
      chebyshev_iterations(dt);
      return finish_local_global(dt);
    }
    for (Eigen::Index i = 0; i < nd; ++i) damp_in(i) = fixed(i) ? -y(i) : 0.0;
    add_product(lg_a, damp_in, lg_components, lg_rhs0);
    for (int it = 0; it < opt.local_global_iterations; ++it) {
      // Local step (Liu et al. 2013): each spring's best direction d_s = l0_s (y_i - y_j)/|y_i - y_j|, as J d.
      lg_jd.setZero();
      for (const model::CentralSprings* b : spring_blocks) b->add_rest_directions(y, lg_jd);
      for (Eigen::Index i = 0; i < nd; ++i) rhs(i) = fixed(i) ? y(i) : lg_rhs0(i) + lg_jd(i);
      lg_factor.solve_in_place(rhs.data(), lg_components);  // global step
      y = rhs;
    }
    return finish_local_global(dt);
  }

  StepReport finish_local_global(double dt) {
    StepReport r;
    r.iterations = opt.local_global_iterations;
    objective_gradient(y, 1.0 / (dt * dt), dt, grad);
    r.residual = grad.norm();
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
  auto is_free = [&](int i) { return !m->problem.fixed_dofs[static_cast<size_t>(i)]; };
  if (m->dyn.mass.size() != nd) throw InvalidArgument("Simulator: the mass vector needs one entry per DOF");
  for (int i = 0; i < nd; ++i)
    if (is_free(i) && !(m->dyn.mass(i) > 0.0))
      throw InvalidArgument("Simulator: free DOF " + std::to_string(i) + " has no mass");
  if (m->dyn.gravity.size() != 0 && m->dyn.gravity.size() != m->model().dim())
    throw InvalidArgument("Simulator: gravity needs one component per axis");
  if (!(m->dyn.mass_damping >= 0.0) || !(m->dyn.stiffness_damping >= 0.0) || !std::isfinite(m->dyn.mass_damping) ||
      !std::isfinite(m->dyn.stiffness_damping))
    throw InvalidArgument("Simulator: Rayleigh damping coefficients must be finite and >= 0");
  if (options.local_global_iterations < 1)
    throw InvalidArgument("Simulator: local-global needs at least 1 iteration per step");
  if (options.max_newton_iterations < 1 || !(options.newton_tolerance > 0.0))
    throw InvalidArgument("Simulator: Newton needs at least 1 iteration and a tolerance > 0");
  if (m->dyn.stiffness_damping > 0.0) m->rest_stiffness();
  if (options.integrator == Integrator::kLocalGlobal) m->setup_local_global();
  m->base_fixed = m->problem.fixed_dofs;
  m->x = model::initial_positions(m->problem);
}

Simulator::~Simulator() = default;
Simulator::Simulator(Simulator&&) noexcept = default;
Simulator& Simulator::operator=(Simulator&&) noexcept = default;

StepReport Simulator::step(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt)) throw InvalidArgument("the time step must be a positive number");
  m->update_loads();
  m->update_probe_targets();
  m->cg_iterations = 0;
  StepReport r;
  switch (m->opt.integrator) {
    case Integrator::kSymplecticEuler: r = m->explicit_step(dt, false); break;
    case Integrator::kVelocityVerlet: r = m->explicit_step(dt, true); break;
    case Integrator::kImplicitEuler: r = m->implicit_step(dt, false); break;
    case Integrator::kQuasiStatic: r = m->implicit_step(dt, true); break;
    case Integrator::kLocalGlobal: r = m->local_global_step(dt); break;
    case Integrator::kImplicitEulerLinearised: r = m->linearised_step(dt); break;
  }
  m->time_s += dt;
  r.linear_iterations = static_cast<int>(m->cg_iterations);
  m->add_probe_force(r);
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
