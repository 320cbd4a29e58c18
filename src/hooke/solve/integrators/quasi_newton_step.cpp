// The quasi-Newton family (Liu, Bouaziz & Kavan 2017, "Quasi-Newton Methods for Real-Time Simulation of
// Hyperelastic Materials", ACM TOG 36(3)): backward Euler's incremental potential of any model, minimised by
// L-BFGS whose initial Hessian is the step's Newton matrix at rest, H0 = M (1/dt^2 + alpha/dt) + (1 + beta/dt) K0,
// factorised once per dt. Every iteration costs one energy with its gradient (one pass) and one prefactored solve:
// local/global's cost for springs, tet volume terms, area terms, anchors, volume penalties and FEM alike.
//
// Two choices beyond the paper, both measured (docs/simulation.md):
// - The curvature pairs (s, y) are kept across steps: y = grad phi(a) - grad phi(b) = (M/dt^2 + D/dt)(a - b) +
//   grad E(a) - grad E(b) does not depend on x_n, v_n or the loads, so a pair of the last step is curvature of this
//   step's objective too. They are dropped when dt or the fixed DOFs change.
// - Nodes grabbed by a probe are held without a new factorisation: for the c DOFs E fixed since H0 was factorised,
//   the constrained solve is z = H0^-1 r - W C^-1 (H0^-1 r)_E with W = H0^-1 E and C = E^T W (a capacitance
//   correction, c solves at the grab), so grabbing costs no refactorisation in a haptic loop.
// - Contact (a barrier against a tool or an obstacle) is stiff where it acts and absent at rest, so H0 alone
//   leaves the L-BFGS steps at their budget there. Its per-node Hessian blocks C at the step's start
//   (TermBlock::add_node_stiffness) are added to H0 by Woodbury's identity on those nodes U:
//   with C = Z Z^T (a column per non-zero eigenvalue of each node's block: one per node for a frictionless barrier),
//   (H0 + Z Z^T)^-1 = H0^-1 - H0^-1 Z (I + Z^T H0^-1 Z)^-1 Z^T H0^-1, H0^-1 Z from W = H0^-1 U, U the contact
//   nodes' DOFs. A node's columns of W cost one solve (three without the Kronecker form) when it first touches and
//   are kept while it stays in the set, so a press costs no refactorisation either (docs/contact.md).
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/core/sparse_cholesky.hpp>
#include <hooke/solve/detail/incremental_potential.hpp>
#include <hooke/solve/detail/integrator_step.hpp>
#include <hooke/solve/detail/sparse_ops.hpp>
#include <vector>

namespace hooke::solve::detail {
namespace {

// Beyond this many DOFs held since the factorisation, H0 is refactorised instead of corrected: the correction
// costs c x DOFs per solve.
constexpr int kMaxCorrectedDofs = 96;
// Contact nodes whose stiffness the initial Hessian carries at most (those with the stiffest blocks beyond it): the
// correction costs 3 x nodes x DOFs per solve.
constexpr int kMaxContactNodes = 48;

class QuasiNewtonStep final : public IntegratorStep {
 public:
  QuasiNewtonStep(SimulationState& s, const SimulatorOptions& options)
      : m_s(s), m_opt(options.quasi_newton), m_objective(s), m_factor(options.newton.backend) {
    const QuasiNewtonOptions& q = m_opt;
    if (q.max_iterations < 1 || q.history < 0 || !(q.tolerance > 0.0 && q.tolerance < 1.0))
      throw InvalidArgument("quasi-newton needs at least 1 iteration, a history >= 0 and a tolerance in (0, 1)");
    for (VecX* w : {&m_y, &m_trial, &m_grad, &m_grad_trial, &m_dir, &m_q}) w->setZero(s.nd);
    m_s_hist.setZero(s.nd, q.history);
    m_y_hist.setZero(s.nd, q.history);
    m_rho.setZero(q.history);
    m_alpha.setZero(q.history);
    // H0 is only the L-BFGS initial Hessian: its solve on a bfloat16 copy of the factor reads a quarter of the
    // double factor's bytes. It is the exact inverse of a nearby SPD matrix (the rounded factor's product), ~4e-3
    // from H0, which the curvature pairs correct: 1.18 -> 1.24 iterations per step on 11 425 nodes, errors
    // unchanged (docs/simulation.md, "Reduced-precision initial Hessian").
    m_factor.set_solve_precision(SolvePrecision::kBfloat16);
  }

  void refix() override {
    m_pairs = 0;
    m_refix = true;
  }

  StepReport step(SimulationState& s, double dt) override {
    if (dt != m_dt) {
      factorize(dt);
    } else if (m_refix) {
      hold_new_dofs();
    }
    m_refix = false;
    update_contact(s);
    m_objective.begin(1.0 / (dt * dt), dt);
    m_y = m_objective.inertial_target();
    m_phi = m_objective.value_and_gradient(m_y, m_grad);
    m_gradient_at_y = true;  // the objective's last gradient() was at m_y (the probe force reuses it)
    m_at_round_off = false;
    StepReport r;
    if (!std::isfinite(m_phi)) {  // x_hat inverts an element: start from where the body is
      m_y = s.x;
      s.apply_prescribed(m_y);
      m_phi = m_objective.value_and_gradient(m_y, m_grad);
      if (!std::isfinite(m_phi)) carry_jump(r);  // the held nodes jumped further than their neighbours reach
    }
    r.iterations += minimise();
    r.residual = m_grad.norm();
    r.converged = done(r.residual);
    s.advance(m_y, dt);
    if (m_gradient_at_y) {  // the probe force without another gradient evaluation
      s.fixed_grad = m_objective.fixed_model_gradient();
      s.fixed_grad_valid = true;
    }
    return r;
  }

 private:
  // Converged: the residual within the tolerance of the step's force scale, or the round-off step test met. An
  // overflowing load (a force of 1e300 N) makes the scale infinite, and every residual would pass the test.
  bool done(double residual) const {
    return m_at_round_off || (std::isfinite(residual) && std::isfinite(m_objective.force_scale()) &&
                              residual <= m_opt.tolerance * m_objective.force_scale());
  }

  // L-BFGS from m_y (objective m_phi, gradient m_grad there) with the fixed DOFs where m_y has them, until done()
  // or the iteration budget; returns the iterations taken.
  int minimise() {
    double residual = m_grad.norm();
    const bool conservative = m_objective.conservative();
    int it = 0;
    for (; it < m_opt.max_iterations; ++it) {
      if (done(residual) || !std::isfinite(residual * m_objective.force_scale())) break;
      two_loop();
      double slope = m_grad.dot(m_dir);
      if (!(slope < 0.0)) {  // the history gives no descent: start it again from H0
        m_pairs = 0;
        two_loop();
        slope = m_grad.dot(m_dir);
        if (!(slope < 0.0)) break;
      }
      // Newton's round-off test (NewtonOptions::step_tolerance): a direction below 1e-13 of the body's size has
      // nothing more to gain. A body at rest with no load starts there: its gradient is round-off, which no
      // tolerance relative to that same gradient can be met by.
      if (is_round_off_step(m_dir, NewtonOptions{}, m_objective.size())) {
        m_at_round_off = true;
        break;
      }
      // Backtracking from the full step: Armijo on phi, or a smaller residual where the forces have no potential.
      double alpha = 1.0, phi_trial = m_phi;
      bool accepted = false;
      for (int ls = 0; ls < 30 && !accepted; ++ls, alpha *= 0.5) {
        m_trial = m_y + alpha * m_dir;
        if (conservative) {  // the gradient with the energy, in one pass: the full step is nearly always taken
          phi_trial = m_objective.value_and_gradient(m_trial, m_grad_trial);
          m_gradient_at_y = false;  // until the trial is accepted
          if (!std::isfinite(phi_trial)) continue;
          accepted =
              phi_trial <= m_phi + 1e-4 * alpha * slope || std::abs(phi_trial - m_phi) <= 1e-13 * std::abs(m_phi);
        } else {
          m_objective.gradient(m_trial, m_grad_trial);
          accepted = std::isfinite(m_grad_trial.norm()) && m_grad_trial.norm() < (1.0 - 1e-4 * alpha) * residual;
          m_gradient_at_y = false;  // until the trial is accepted
        }
      }
      if (!accepted) break;
      push_pair();
      m_gradient_at_y = true;  // at the accepted trial, the new m_y
      m_y.swap(m_trial);
      m_grad.swap(m_grad_trial);
      m_phi = phi_trial;
      residual = m_grad.norm();
    }
    return it;
  }

  // m_y has the fixed DOFs at their targets and inverts an element. The jump J of the fixed DOFs (targets minus
  // where they are) is carried into the body in stages: each moves them by a fraction of J together with its linear
  // extension into the free DOFs (add_extension) and minimises there; a stage whose start inverts an element is
  // halved. The last stage leaves the fixed DOFs exactly at their targets for the step's own minimisation.
  // Without it a grab that moves further in one deformation step than the tets beside it are wide (a multirate
  // haptic loop's step of a second on 100 k nodes) leaves the body inverted for good.
  void carry_jump(StepReport& r) {
    const VecX target = m_y;
    m_y = m_s.x;
    m_phi = m_objective.value_and_gradient(m_y, m_grad);
    if (!std::isfinite(m_phi)) {  // inverted already: nothing to carry from
      m_y = target;
      m_phi = m_objective.value_and_gradient(m_y, m_grad);
      return;
    }
    m_jump = target - m_y;  // zero on the free DOFs
    double reached = 0.0, stage = 1.0;
    while (reached < 1.0 && stage >= 1.0 / 1024.0) {
      const double to = std::min(1.0, reached + stage);
      m_trial = m_y;
      add_extension((to - reached) * m_jump, m_trial);
      if (to == 1.0) m_s.apply_prescribed(m_trial);  // exactly, not to round-off
      const double phi = m_objective.value_and_gradient(m_trial, m_grad_trial);
      m_gradient_at_y = false;
      if (!std::isfinite(phi)) {
        stage *= 0.5;
        continue;
      }
      m_y.swap(m_trial);
      m_grad.swap(m_grad_trial);
      m_phi = phi;
      m_gradient_at_y = true;
      reached = to;
      if (reached < 1.0) {
        r.iterations += minimise();
        m_at_round_off = false;  // of this stage, not of the step
      }
    }
    if (reached < 1.0) {  // the step's own minimisation reports what is left (an inverted element)
      m_y = target;
      m_phi = m_objective.value_and_gradient(m_y, m_grad);
      m_gradient_at_y = true;
    }
  }

  // z += the linear extension of a move dj of the fixed DOFs (dj zero on the free ones): dj itself on the fixed DOFs
  // and -H0_ff^-1 H0_fh dj on the free ones, the free DOFs' response to it under H0 (H0_fh from the rest stiffness;
  // the masses are diagonal).
  void add_extension(const VecX& dj, VecX& z) {
    const SparseMatrix& k = m_s.rest_stiffness();
    const int d = m_s.model().dim(), r = m_components;
    m_q.setZero();
    for (Eigen::Index col = 0; col < m_s.nd; ++col) {
      if (!m_s.fixed(col) || dj(col) == 0.0) continue;
      for (SparseMatrix::InnerIterator it(k, col); it; ++it) {
        if (m_s.fixed(it.row())) continue;
        if (r == 1) {
          m_q(it.row()) -= m_k_weight * it.value() * dj(col);
        } else if (it.row() % d == col % d) {  // Kronecker form: the node pair's trace acts on every axis
          const Eigen::Index u = it.row() / d, c = col / d;
          for (int a = 0; a < d; ++a) m_q(d * u + a) -= m_k_weight * it.value() * dj(d * c + a);
        }
      }
    }
    apply_h0_inverse(m_q);
    z += m_q + dj;
  }
  // H0 on the current fixed DOFs (identity rows and columns there), factorised. kRest: the Newton matrix at rest,
  // its PSD projection where the exact one is not positive definite (negative volume terms of an indefinite
  // assembly, prestrain). kIsotropic: one per-node matrix for all axes (Kronecker form, like local/global's), each
  // node pair's 3 x 3 block of K0 replaced by its trace (times QuasiNewtonOptions::isotropic_scale / dim), for
  // models whose masses are equal on a node's axes and whose nodes are fixed on all axes or none.
  void factorize(double dt) {
    const double mass_factor = 1.0 / (dt * dt) + m_s.dyn.mass_damping / dt;
    const double k_factor = 1.0 + m_s.dyn.stiffness_damping / dt;
    const int d = m_s.model().dim();
    const std::vector<char>& fixed = m_s.problem.fixed_dofs;
    const bool isotropic = m_opt.initial_hessian == QuasiNewtonHessian::kIsotropic ||
                           (m_opt.initial_hessian == QuasiNewtonHessian::kAuto && !m_s.model().exact_hessian());
    const bool kronecker = isotropic && m_s.axes_alike();
    m_components = kronecker ? d : 1;
    for (bool project : {false, true}) {
      model::HessianAssembly& a = m_s.hessian_assembly();
      if (project)
        a.assemble(m_s.model().rest_positions(), true);
      else
        a.matrix() = m_s.rest_stiffness();  // same pattern
      SparseMatrix h;
      if (kronecker) {
        const double w = k_factor * m_opt.isotropic_scale / d;
        std::vector<Triplet> t;
        for (int c = 0; c < a.matrix().outerSize(); ++c)
          for (SparseMatrix::InnerIterator it(a.matrix(), c); it; ++it)
            if (it.row() % d == c % d) t.emplace_back(static_cast<int>(it.row()) / d, c / d, w * it.value());
        for (Eigen::Index u = 0; u < m_s.nd / d; ++u) t.emplace_back(u, u, mass_factor * m_s.dyn.mass(d * u));
        h.resize(m_s.nd / d, m_s.nd / d);
        h.setFromTriplets(t.begin(), t.end());
      } else {
        h = a.matrix() * k_factor;
        for (Eigen::Index i = 0; i < m_s.nd; ++i)
          h.valuePtr()[a.diagonal()[static_cast<size_t>(i)]] += mass_factor * m_s.dyn.mass(i);
      }
      constrain(h, fixed, m_components);
      if (m_factor.factorize(h)) {
        m_k_weight = kronecker ? k_factor * m_opt.isotropic_scale / d : k_factor;
        m_dt = dt;
        m_factor_fixed = fixed;
        m_held.clear();
        m_pairs = 0;
        m_contact_nodes.clear();  // their columns of W were solved with the old factor
        return;
      }
    }
    throw SolverFailure("quasi-newton: the step's matrix at rest is not positive definite even projected");
  }

  // The DOFs fixed since the factorisation, held by the capacitance correction (or a new factorisation when DOFs
  // were released or too many were added). In Kronecker form the held unknowns are nodes, shared by all axes.
  void hold_new_dofs() {
    const std::vector<char>& fixed = m_s.problem.fixed_dofs;
    const int r = m_components;
    std::vector<int> held;
    for (size_t i = 0; i < fixed.size(); ++i) {
      if (m_factor_fixed[i] && !fixed[i]) return factorize(m_dt);  // released: H0 has an identity row there
      if (fixed[i] != fixed[i - i % static_cast<size_t>(r)]) return factorize(m_dt);  // not whole nodes
      if (fixed[i] && !m_factor_fixed[i] && i % static_cast<size_t>(r) == 0) held.push_back(static_cast<int>(i) / r);
    }
    if (static_cast<int>(held.size()) * r > kMaxCorrectedDofs) return factorize(m_dt);
    m_held = held;
    const auto c = static_cast<Eigen::Index>(held.size()), n = m_s.nd / r;
    m_w.setZero(n, c);
    for (Eigen::Index k = 0; k < c; ++k) {
      m_w(held[static_cast<size_t>(k)], k) = 1.0;
      m_factor.solve_in_place(m_w.col(k).data(), 1);
    }
    MatX cap(c, c);
    for (Eigen::Index k = 0; k < c; ++k)
      for (Eigen::Index j = 0; j < c; ++j) cap(k, j) = m_w(held[static_cast<size_t>(k)], j);
    m_capacitance.compute(cap);
    m_lambda.setZero(c, r);
    m_contact_nodes.clear();  // their columns of W were solved without these held DOFs
  }

  // The contact stiffness at the step's start (s.x) into the Woodbury correction: new nodes' columns of W solved,
  // Z from C's blocks and the Cholesky of I + Z^T H0^-1 Z. Nothing when no block has node stiffness.
  void update_contact(const SimulationState& s) {
    m_contact_active = false;
    if (!s.model().node_stiffness(s.x, m_node_stiffness) && m_contact_nodes.empty()) return;
    const int d = s.model().dim();
    if (d != 3) return;
    // Per node: the sum of the blocks' 3 x 3 matrices, fixed nodes left out; the stiffest kMaxContactNodes kept.
    m_merged.clear();
    for (const auto& [node, h] : m_node_stiffness) {
      if (s.fixed(3 * node)) continue;
      auto it = std::find_if(m_merged.begin(), m_merged.end(), [&](const auto& e) { return e.first == node; });
      if (it == m_merged.end())
        m_merged.emplace_back(node, h);
      else
        it->second += h;
    }
    if (static_cast<int>(m_merged.size()) > kMaxContactNodes) {
      std::nth_element(m_merged.begin(), m_merged.begin() + kMaxContactNodes, m_merged.end(),
                       [](const auto& a, const auto& b) { return a.second.trace() > b.second.trace(); });
      m_merged.resize(kMaxContactNodes);
    }
    // Nodes that left the set keep their columns (C = 0 there) unless the set would outgrow its bound.
    std::size_t kept = m_contact_nodes.size();
    for (const auto& [node, h] : m_merged)
      if (std::find(m_contact_nodes.begin(), m_contact_nodes.end(), node) == m_contact_nodes.end()) ++kept;
    if (static_cast<int>(kept) > kMaxContactNodes) drop_contact_columns_except(m_merged);
    for (const auto& [node, h] : m_merged)
      if (std::find(m_contact_nodes.begin(), m_contact_nodes.end(), node) == m_contact_nodes.end())
        add_contact_columns(node);
    // C = Z Z^T with Z's columns sqrt(eigenvalue) x eigenvector of each node's block (one per node for a
    // frictionless barrier, whose block is kappa b'' n n^T): the small system is m x m, m the columns.
    m_contact_cols.clear();
    for (const auto& [node, h] : m_merged) {
      const auto j =
          static_cast<int>(std::find(m_contact_nodes.begin(), m_contact_nodes.end(), node) - m_contact_nodes.begin());
      const Eigen::SelfAdjointEigenSolver<Mat3> eig(h);
      const double largest = eig.eigenvalues().maxCoeff();
      for (int a = 0; a < 3; ++a)
        if (largest > 0.0 && eig.eigenvalues()(a) > 1e-12 * largest)
          m_contact_cols.push_back({j, Vec3(std::sqrt(eig.eigenvalues()(a)) * eig.eigenvectors().col(a))});
    }
    const auto m = static_cast<Eigen::Index>(m_contact_cols.size());
    if (m == 0) return;
    m_contact_m.resize(m, m);  // I + Z^T H0^-1 Z
    for (Eigen::Index p = 0; p < m; ++p)
      for (Eigen::Index q = 0; q <= p; ++q) {
        const ContactColumn &a = m_contact_cols[static_cast<size_t>(p)], &b = m_contact_cols[static_cast<size_t>(q)];
        Mat3 block;  // U_a^T H0^-1 U_b
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c)
            block(r, c) = contact_column_entry(3 * b.slot + c, 3 * m_contact_nodes[a.slot] + r);
        m_contact_m(p, q) = m_contact_m(q, p) = a.v.dot(block * b.v) + (p == q ? 1.0 : 0.0);
      }
    m_contact_solver.compute(m_contact_m);
    m_contact_active = m_contact_solver.info() == Eigen::Success;
  }

  // W's columns for `node`: H0^-1 e for its three DOFs (one solve of the Kronecker form's per-node matrix, three
  // otherwise).
  void add_contact_columns(int node) {
    const auto k = static_cast<Eigen::Index>(m_contact_nodes.size());
    if (m_components == 3) {
      m_contact_w.conservativeResize(m_s.nd / 3, k + 1);
      m_q.setZero();
      m_q.segment<3>(3 * node).setOnes();
      apply_h0_inverse_held(m_q);
      for (Eigen::Index u = 0; u < m_s.nd / 3; ++u) m_contact_w(u, k) = m_q(3 * u);
    } else {
      m_contact_w.conservativeResize(m_s.nd, 3 * (k + 1));
      for (int a = 0; a < 3; ++a) {
        m_q.setZero();
        m_q(3 * node + a) = 1.0;
        apply_h0_inverse_held(m_q);
        m_contact_w.col(3 * k + a) = m_q;
      }
    }
    m_contact_nodes.push_back(node);
  }

  // Drops W's columns of the contact nodes not in `keep` (their solves are what a column costs, so those still in
  // contact keep theirs: a contact set larger than the bound then changes only at its edge, measured on the 11 425-node
  // cylinder under a sphere, where clearing all of them every step took 0.3 s).
  void drop_contact_columns_except(const std::vector<std::pair<int, Mat3>>& keep) {
    const Eigen::Index per = m_components == 3 ? 1 : 3;
    Eigen::Index next = 0;
    std::vector<int> nodes;
    for (size_t j = 0; j < m_contact_nodes.size(); ++j) {
      const int node = m_contact_nodes[j];
      if (std::find_if(keep.begin(), keep.end(), [&](const auto& e) { return e.first == node; }) == keep.end())
        continue;
      if (next != static_cast<Eigen::Index>(j))
        m_contact_w.middleCols(per * next, per) = m_contact_w.middleCols(per * static_cast<Eigen::Index>(j), per);
      nodes.push_back(node);
      ++next;
    }
    m_contact_w.conservativeResize(Eigen::NoChange, per * next);
    m_contact_nodes = std::move(nodes);
  }

  // Entry `row` (a DOF) of W's column l (3 per contact node).
  double contact_column_entry(Eigen::Index l, Eigen::Index row) const {
    if (m_components == 3) return row % 3 == l % 3 ? m_contact_w(row / 3, l / 3) : 0.0;
    return m_contact_w(row, l);
  }

  // z = H0^-1 z on the current free DOFs, in place, with the contact correction: z -= H0^-1 Z (I + Z^T H0^-1 Z)^-1
  // Z^T z, H0^-1 Z from W's columns (per node slot, the sum of its columns' vectors times their weights).
  void apply_h0_inverse(VecX& z) {
    apply_h0_inverse_held(z);
    if (!m_contact_active) return;
    const auto m = static_cast<Eigen::Index>(m_contact_cols.size());
    m_contact_t.resize(m);
    for (Eigen::Index p = 0; p < m; ++p) {
      const ContactColumn& c = m_contact_cols[static_cast<size_t>(p)];
      m_contact_t(p) = c.v.dot(z.segment<3>(3 * m_contact_nodes[static_cast<size_t>(c.slot)]));
    }
    m_contact_solver.solveInPlace(m_contact_t);
    m_slot_weight.setZero(3, static_cast<Eigen::Index>(m_contact_nodes.size()));
    for (Eigen::Index p = 0; p < m; ++p) {
      const ContactColumn& c = m_contact_cols[static_cast<size_t>(p)];
      m_slot_weight.col(c.slot) += m_contact_t(p) * c.v;
    }
    for (Eigen::Index j = 0; j < m_slot_weight.cols(); ++j) {
      const Vec3 a = m_slot_weight.col(j);
      if (a.isZero(0.0)) continue;
      if (m_components == 3) {
        const double* w = m_contact_w.col(j).data();
        for (Eigen::Index u = 0; u < m_contact_w.rows(); ++u) z.segment<3>(3 * u) -= w[u] * a;
      } else {
        z.noalias() -= m_contact_w.middleCols<3>(3 * j) * a;
      }
    }
  }

  // z = H0^-1 z on the current free DOFs, in place (the factor and the held DOFs' correction).
  void apply_h0_inverse_held(VecX& z) {
    const int r = m_components;
    m_factor.solve_in_place(z.data(), r);
    if (m_held.empty()) return;
    for (size_t k = 0; k < m_held.size(); ++k)
      for (int a = 0; a < r; ++a) m_lambda(static_cast<Eigen::Index>(k), a) = z(r * m_held[k] + a);
    m_capacitance.solveInPlace(m_lambda);
    // z -= W lambda, W column by column (n x c, column-major: a row-wise sum would stride n doubles per term).
    for (Eigen::Index k = 0; k < m_w.cols(); ++k) {
      const double* w = m_w.col(k).data();
      for (int a = 0; a < r; ++a) {
        const double l = m_lambda(k, a);
        for (Eigen::Index u = 0; u < m_w.rows(); ++u) z(r * u + a) -= w[u] * l;
      }
    }
    for (int u : m_held)
      for (int a = 0; a < r; ++a) z(r * u + a) = 0.0;  // exactly, not to round-off
  }

  // L-BFGS two-loop recursion (Nocedal & Wright, Numerical Optimization, 2nd ed., Alg. 7.4): m_dir = -H grad with
  // H0^-1 in the middle; the pairs are stored in a ring, the newest at m_newest.
  void two_loop() {
    m_q = m_grad;
    const int m = m_opt.history;
    for (int k = 0; k < m_pairs; ++k) {
      const int i = (m_newest - k + m) % m;
      m_alpha(i) = m_rho(i) * m_s_hist.col(i).dot(m_q);
      m_q.noalias() -= m_alpha(i) * m_y_hist.col(i);
    }
    apply_h0_inverse(m_q);
    for (int k = m_pairs - 1; k >= 0; --k) {
      const int i = (m_newest - k + m) % m;
      const double beta = m_rho(i) * m_y_hist.col(i).dot(m_q);
      m_q.noalias() += (m_alpha(i) - beta) * m_s_hist.col(i);
    }
    m_dir = -m_q;
  }

  // Stores s = trial - y, y = grad(trial) - grad(y) when its curvature is positive.
  void push_pair() {
    const int m = m_opt.history;
    if (m == 0) return;
    double sy = 0.0;
    for (Eigen::Index i = 0; i < m_s.nd; ++i) sy += (m_trial(i) - m_y(i)) * (m_grad_trial(i) - m_grad(i));
    if (!(sy > 1e-300)) return;  // no positive curvature along the step (round-off, a non-convex region): skip it
    const int slot = (m_newest + 1) % m;
    m_s_hist.col(slot) = m_trial - m_y;
    m_y_hist.col(slot) = m_grad_trial - m_grad;
    m_rho(slot) = 1.0 / sy;
    m_newest = slot;
    m_pairs = std::min(m_pairs + 1, m);
  }

  SimulationState& m_s;
  QuasiNewtonOptions m_opt;
  IncrementalPotential m_objective;
  SparseCholesky m_factor;  // of H0 with m_factor_fixed's rows and columns those of the identity
  std::vector<char> m_factor_fixed;
  double m_dt = -1.0;
  double m_k_weight = 1.0;  // H0's off-diagonal entries over the rest stiffness's (Kronecker form: per trace)
  bool m_refix = false;
  int m_components = 1;            // 1: H0 acts on DOFs; dim: one per-node matrix for all axes (Kronecker)
  std::vector<int> m_held;         // unknowns fixed since the factorisation (the capacitance correction's E)
  MatX m_w;                        // H0^-1 E, unknowns x c
  Eigen::LLT<MatX> m_capacitance;  // of C = E^T H0^-1 E
  MatX m_lambda;                   // c x components
  // The contact correction: its nodes, W's columns (Kronecker form: one per node, per-node unknowns; else three per
  // node, DOFs), Z's columns, I + Z^T H0^-1 Z and its Cholesky, whether it applies this step, and scratch.
  struct ContactColumn {
    int slot;  // index in m_contact_nodes
    Vec3 v;    // the column's part at that node: C's block there is the sum of v v^T over its columns
  };
  std::vector<int> m_contact_nodes;
  std::vector<ContactColumn> m_contact_cols;
  MatX m_contact_w, m_contact_m, m_slot_weight;
  Eigen::LLT<MatX> m_contact_solver;
  bool m_contact_active = false;
  VecX m_contact_t;
  std::vector<std::pair<int, Mat3>> m_node_stiffness, m_merged;
  MatX m_s_hist, m_y_hist;  // DOFs x history, a ring
  VecX m_rho, m_alpha;
  int m_pairs = 0, m_newest = -1;
  VecX m_y, m_trial, m_grad, m_grad_trial, m_dir, m_q, m_jump;
  double m_phi = 0.0;           // the objective at m_y
  bool m_gradient_at_y = true;  // m_objective's last gradient was at m_y (the probe force reuses it)
  bool m_at_round_off = false;  // the round-off step test was met
};

}  // namespace

std::unique_ptr<IntegratorStep> make_quasi_newton_step(SimulationState& s, const SimulatorOptions& options) {
  return std::make_unique<QuasiNewtonStep>(s, options);
}

}  // namespace hooke::solve::detail
