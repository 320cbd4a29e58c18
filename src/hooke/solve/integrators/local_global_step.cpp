// The local/global family (Liu, Bargteil, O'Brien, Kavan 2013, "Fast Simulation of Mass-Spring Systems"): the
// incremental potential of implicit Euler for central-spring models, minimised by alternating spring directions
// (local) and one constant linear system (global), solved by a prefactored Cholesky or by Chebyshev-accelerated
// Jacobi sweeps (Wang 2015).
#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/core/sparse_cholesky.hpp>
#include <hooke/core/symmetric_eigen.hpp>
#include <hooke/solve/detail/incremental_potential.hpp>
#include <hooke/solve/detail/integrator_step.hpp>
#include <hooke/solve/detail/sparse_ops.hpp>
#include <string>

namespace hooke::solve::detail {
namespace {

class LocalGlobalStep final : public IntegratorStep {
 public:
  LocalGlobalStep(SimulationState& s, const SimulatorOptions& options) : m_s(s), m_opt(options), m_objective(s) {
    for (VecX* w : {&m_y, &m_rhs, &m_delta, &m_damp_in, &m_damp_out, &m_x_n, &m_x_hat}) w->setZero(s.nd);
    setup();
  }
  void refix() override { m_dt = -1.0; }

  void setup() {
    for (const auto& b : m_s.model().blocks()) {
      if (!b->has_forces()) continue;  // admissibility only (the orientation guard): checked by energy()
      const model::CentralSprings* springs = b->central_springs();
      if (!springs)
        throw InvalidArgument("local-global needs a model of central springs only; this one has a '" +
                              std::string(b->name()) + "' block (use implicit-euler)");
      m_spring_blocks.push_back(springs);
      m_spring_terms.push_back(b.get());
    }
    m_rhs0.setZero(m_s.nd);
    m_jd.setZero(m_s.nd);
  }

  // The global matrix M/dt^2 + D/dt + sum_s k_s (e_i - e_j)(e_i - e_j)^T. Without stiffness damping, with equal
  // masses on a node's axes and nodes fixed on all axes or none, it is (per-node matrix) x I_dim: one factor of
  // a #nodes-square matrix then serves every axis (Kronecker form).
  void setup_global_matrix(double dt) {
    const int d = m_s.model().dim();
    m_components = m_s.dyn.stiffness_damping == 0.0 && m_s.axes_alike() ? d : 1;
    const int r = m_components, n = static_cast<int>(m_s.nd) / r, axes = d / r;
    std::vector<Triplet> t;
    for (const model::CentralSprings* b : m_spring_blocks)
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
      const double m = m_s.dyn.mass(r * u);
      t.emplace_back(u, u, m / (dt * dt) + m_s.dyn.mass_damping * m / dt);
    }
    m_a.resize(n, n);
    m_a.setFromTriplets(t.begin(), t.end());
    if (m_s.dyn.stiffness_damping > 0.0) m_a += (m_s.dyn.stiffness_damping / dt) * m_s.rest_stiffness();
    m_dt = dt;
    if (m_opt.global_solve == GlobalSolve::kChebyshev) {
      setup_chebyshev(dt);
      return;
    }
    SparseMatrix constrained = m_a;
    constrain(constrained, m_s.problem.fixed_dofs, r);
    if (!m_global_factor.factorize(constrained))
      throw SolverFailure("the local-global system matrix is not positive definite");
  }

  // The Chebyshev global step (docs/simulation.md). Each iteration refreshes the local step's directions, so the
  // error of the step's solution m_y* contracts, near it, like a Jacobi-preconditioned Richardson iteration on the
  // true Newton matrix H = M/dt^2 + D/dt + K (the directions' derivative turns L into the springs' stiffness):
  // after k iterations it is P_k(D^-1 H) times the initial error, P_k the Chebyshev polynomial of the interval
  // [a, b] that holds the spectrum of D^-1 H, |P_k| <= 1 / T_k((b + a) / (b - a)) on it (D = diag A).
  // - b = 2: D^-1 H <= D^-1 A <= 2 (H <= A for springs at or beyond their rest length; Gershgorin on the diagonally
  //   dominant A).
  // - a: the smallest Ritz value of D^-1/2 H D^-1/2 at rest (Lanczos over the free DOFs), raised where needed for
  //   the stability of the time step: a step that ends at m_y* + P (m_x_hat - m_y*) maps a mode (x, v) with the
  //   amplification matrix [[g, g dt], [(g - 1) / dt, g]], g = s + P (1 - s), s in (0, 1] (s = 1 for a mode without
  //   stiffness), whose eigenvalues g +- sqrt(g^2 - g) lie in the unit disc only for -1/3 <= g <= 1. P may
  //   therefore not dip below -1/3 on stiff modes (s -> 0): with few iterations the interval is cut from below
  //   until 1 / T_k((b + a) / (b - a)) <= 1/4. Modes below a then converge monotonically (0 < P < 1), more slowly.
  //   (The test with 10 iterations on the 1 089-node cylinder: the bound at 0.26 settles, at 0.46 it oscillates.)
  void setup_chebyshev(double dt) {
    const int r = m_components;
    m_inv_diag.setZero(m_s.nd);
    m_previous.setZero(m_s.nd);
    for (Eigen::Index i = 0; i < m_s.nd; ++i)
      if (!m_s.fixed(i)) m_inv_diag(i) = 1.0 / m_a.coeff(i / r, i / r);
    m_b = 2.0;
    const double k_it = m_opt.local_global_iterations;
    const double sigma_stable = std::cosh(std::acosh(4.0) / k_it);  // T_k(sigma_stable) = 4
    m_a_min = m_b * (sigma_stable - 1.0) / (sigma_stable + 1.0);
    if (!m_opt.chebyshev_acceleration) return;
    const SparseMatrix& k = m_s.rest_stiffness();
    const double k_scale = 1.0 + m_s.dyn.stiffness_damping / dt;
    const VecX scale = m_inv_diag.cwiseSqrt(),
               mass_scale = m_s.dyn.mass * (1.0 / (dt * dt) + m_s.dyn.mass_damping / dt);
    auto apply = [&](const VecX& z, VecX& out) {  // out = D^-1/2 H D^-1/2 z on the free DOFs
      const VecX sz = scale.cwiseProduct(z);
      multiply(k, sz, out);
      out = scale.cwiseProduct(k_scale * out + mass_scale.cwiseProduct(sz));
    };
    const Eigen::Index free = (m_inv_diag.array() > 0.0).count();
    const int steps = static_cast<int>(std::min<Eigen::Index>(80, free));
    if (steps == 0) return;
    VecX q = VecX::Zero(m_s.nd), q_prev = VecX::Zero(m_s.nd), w(m_s.nd);
    for (Eigen::Index i = 0; i < m_s.nd; ++i)
      if (m_inv_diag(i) > 0.0) q(i) = 1.0 + 0.3 * std::sin(1.0 + 7.0 * static_cast<double>(i));
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
    const VecX ritz = symmetric_eigenvalues(t);
    m_lo = std::clamp(ritz(0), m_a_min, m_b);
  }

  // Chebyshev iteration (e.g. Saad, Iterative Methods for Sparse Linear Systems, 2nd ed., Alg. 12.1) with the
  // Jacobi preconditioner on the step's nonlinear residual, restarted every step: theta = (b + a) / 2,
  // delta = (b - a) / 2; d_0 = D^-1 r_0 / theta; d_k = rho_k rho_{k-1} d_{k-1} + 2 rho_k / delta D^-1 r_k with
  // rho_0 = delta / theta, rho_k = 1 / (2 theta / delta - rho_{k-1}); y += d_k. The residual needs the local step's
  // J d(y) and the Laplacian's L y only as J d - L y = -dE_springs/dy, so each iteration is one spring-gradient
  // pass: r = rhs0 - M (1/dt^2 + alpha/dt) y - beta/dt K0 y - dE/dy. Without acceleration: y += D^-1 r (Jacobi).
  void chebyshev_iterations(double dt) {
    const double a = m_opt.chebyshev_acceleration ? m_lo : m_a_min;
    const double theta = 0.5 * (m_b + a), half_width = 0.5 * (m_b - a);
    const double mass_factor = 1.0 / (dt * dt) + m_s.dyn.mass_damping / dt;
    double rho = half_width / theta;
    for (int it = 0; it < m_opt.local_global_iterations; ++it) {
      m_delta.setZero();
      for (const model::TermBlock* b : m_spring_terms) b->add_gradient(m_y, m_delta);
      if (m_s.dyn.stiffness_damping > 0.0) {
        multiply(m_s.rest_stiffness(), m_y, m_damp_out);
        m_delta += (m_s.dyn.stiffness_damping / dt) * m_damp_out;
      }
      const double rho_next = it == 0 ? rho : 1.0 / (2.0 * theta / half_width - rho);
      const double keep = it == 0 ? 0.0 : rho_next * rho, push = it == 0 ? 1.0 / theta : 2.0 * rho_next / half_width;
      for (Eigen::Index i = 0; i < m_s.nd; ++i) {
        const double z =
            (m_rhs0(i) - mass_factor * m_s.dyn.mass(i) * m_y(i) - m_delta(i)) * m_inv_diag(i);  // 0 if fixed
        m_previous(i) = m_opt.chebyshev_acceleration ? keep * m_previous(i) + push * z : z;
        m_y(i) += m_previous(i);
      }
      rho = rho_next;
    }
  }

  StepReport step(SimulationState&, double dt) override {
    if (dt != m_dt) setup_global_matrix(dt);
    m_x_n = m_s.x;
    m_x_hat = m_s.x + dt * m_s.v;
    m_y = m_x_hat;
    m_s.apply_prescribed(m_y);
    // Right-hand side without the springs: M x_hat / dt^2 + f + D x_n / dt - A (fixed part of y).
    m_rhs0 = m_s.dyn.mass.cwiseProduct(m_x_hat) / (dt * dt) + m_s.f_total;
    if (m_s.damped()) {
      m_s.damping_product(m_x_n, m_damp_out);
      m_rhs0 += m_damp_out / dt;
    }
    if (m_opt.global_solve == GlobalSolve::kChebyshev) {
      chebyshev_iterations(dt);
      return finish_local_global(dt);
    }
    for (Eigen::Index i = 0; i < m_s.nd; ++i) m_damp_in(i) = m_s.fixed(i) ? -m_y(i) : 0.0;
    add_product(m_a, m_damp_in, m_components, m_rhs0);
    for (int it = 0; it < m_opt.local_global_iterations; ++it) {
      // Local step (Liu et al. 2013): each spring's best direction d_s = l0_s (y_i - y_j)/|y_i - y_j|, as J d.
      m_jd.setZero();
      for (const model::CentralSprings* b : m_spring_blocks) b->add_rest_directions(m_y, m_jd);
      for (Eigen::Index i = 0; i < m_s.nd; ++i) m_rhs(i) = m_s.fixed(i) ? m_y(i) : m_rhs0(i) + m_jd(i);
      m_global_factor.solve_in_place(m_rhs.data(), m_components);  // global step
      m_y = m_rhs;
    }
    return finish_local_global(dt);
  }

  StepReport finish_local_global(double dt) {
    StepReport r;
    r.iterations = m_opt.local_global_iterations;
    m_objective.begin(1.0 / (dt * dt), dt);
    m_objective.gradient(m_y, m_delta);
    r.residual = m_delta.norm();  // of the implicit step's equations: what the fixed iteration count leaves
    m_s.advance(m_y, dt);
    return r;
  }

 private:
  SimulationState& m_s;
  SimulatorOptions m_opt;
  IncrementalPotential m_objective;  // the step's residual
  // The spring blocks. Liu et al. 2013 write the springs' part of the incremental potential as a minimum over
  // directions d_s, |d_s| = l0_s, of sum_s k_s/2 |x_i - x_j - d_s|^2, which makes the global step one constant
  // linear system.
  std::vector<const model::CentralSprings*> m_spring_blocks;
  std::vector<const model::TermBlock*> m_spring_terms;  // the same blocks, for their gradients
  int m_components = 1;            // 1: the system acts on DOFs; dim: one per-node matrix for all axes (Kronecker)
  SparseMatrix m_a;                // M/dt^2 + D/dt + L, unconstrained
  SparseCholesky m_global_factor;  // of m_a with the fixed unknowns' rows and columns replaced by the identity's
  double m_dt = -1.0;
  VecX m_rhs0, m_jd;
  VecX m_inv_diag, m_previous;   // chebyshev: 1 / diag(A) per DOF (0 on fixed DOFs), the last update
  double m_lo = 0.0, m_b = 2.0;  // chebyshev: the interval [lo, b] of D^-1 H it is tuned to
  double m_a_min = 0.0;          // chebyshev: the lowest a that keeps the time step stable
  VecX m_y, m_rhs, m_delta, m_damp_in, m_damp_out, m_x_n, m_x_hat;
};

}  // namespace

std::unique_ptr<IntegratorStep> make_local_global_step(SimulationState& s, const SimulatorOptions& options) {
  return std::make_unique<LocalGlobalStep>(s, options);
}

}  // namespace hooke::solve::detail
