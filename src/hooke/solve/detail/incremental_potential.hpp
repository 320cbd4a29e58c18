#pragma once
// The objective of an implicit time step for the Newton core: backward Euler's incremental potential
//   phi(z) = E(z) - f.(z - X) + |z - x_hat|^2_M / (2 dt^2) + (z - x_n)^T D (z - x_n) / (2 dt),
// x_hat = x_n + dt v_n (fixed DOFs at their targets), whose minimiser is x_{n+1}; or, with w = 0 and dt = 0, the
// static potential E(z) - f.(z - X) of a quasi-static step.
#include <hooke/solve/detail/simulation_state.hpp>
#include <hooke/solve/detail/sparse_ops.hpp>
#include <hooke/solve/newton.hpp>

namespace hooke::solve::detail {

class IncrementalPotential final : public NewtonObjective {
 public:
  explicit IncrementalPotential(SimulationState& s);
  // Starts a step from the state s.x, s.v: w = 1/dt^2 (or 0), dt the damping term's step (or 0).
  void begin(double w, double dt);
  const VecX& inertial_target() const { return m_x_hat; }  // x_hat, m

  bool conservative() const override { return m_s.model().conservative(); }
  bool exact_hessian() const override { return m_s.model().exact_hessian(); }
  const std::vector<char>& fixed() const override { return m_s.problem.fixed_dofs; }
  int dim() const override { return m_s.model().dim(); }
  double size() const override { return m_size; }
  double value(const VecX& z) override;
  void gradient(const VecX& z, VecX& out) override;
  /// value(z), returned, and gradient(z, out) with one pass over each block's elements.
  double value_and_gradient(const VecX& z, VecX& out);
  // |f| on the free DOFs + |gradient| at the step's first gradient evaluation, N.
  double force_scale() const override { return m_scale; }
  // H(z) + w M + D / dt, fixed DOFs replaced by the identity.
  SparseMatrix& newton_matrix(const VecX& z, bool project) override;
  const std::vector<int>& diagonal() const override { return m_s.hessian_assembly().diagonal(); }
  // dE/dx (the model's forces alone, N) on the fixed DOFs at the z of the last gradient() call; other entries 0.
  const VecX& fixed_model_gradient() const { return m_fixed_gradient; }

 private:
  // phi(z) from the model's energy e at z; e itself when it is not finite.
  double potential(const VecX& z, double e);
  // The model's dE/dx at z in `out` to phi's gradient (loads, inertia, damping, fixed DOFs zeroed).
  void finish_gradient(const VecX& z, VecX& out);

  SimulationState& m_s;
  double m_w = 0.0, m_dt = 0.0, m_size = 1.0, m_scale = -1.0, m_load = 0.0;
  VecX m_x_n, m_x_hat, m_dz, m_damping;  // start, inertial target, scratch
  VecX m_fixed_gradient;
  Constraint m_constraint;  // the fixed DOFs' rows and columns in the Newton matrix
};

}  // namespace hooke::solve::detail
