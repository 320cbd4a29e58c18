#pragma once
// What every time integrator of the Simulator reads and writes: the problem, the dynamics, the state, the step's
// loads, and the matrices at rest they share.
#include <hooke/model/hessian_assembly.hpp>
#include <hooke/solve/simulator.hpp>
#include <memory>

namespace hooke::solve::detail {

struct SimulationState {
  model::Problem problem;
  Dynamics dyn;
  Eigen::Index nd = 0;  // DOF count
  VecX x, v;            // positions (m) and velocities (m/s), flat
  VecX f_total;         // the step's loads: dead forces, gravity, a pushing probe, N
  VecX grad;            // dE/dx at x when gradient_valid (explicit steps reuse the probe force's evaluation)
  bool gradient_valid = false;
  VecX fixed_grad;  // dE/dx at x on the fixed DOFs (0 elsewhere) when fixed_grad_valid: the probe force's input
  bool fixed_grad_valid = false;

  SimulationState(model::Problem p, Dynamics d);

  const model::Model& model() const { return *problem.model; }
  bool fixed(Eigen::Index i) const { return problem.fixed_dofs[static_cast<size_t>(i)] != 0; }
  bool damped() const { return dyn.mass_damping > 0.0 || dyn.stiffness_damping > 0.0; }
  // The model's Hessian on a fixed pattern, built at first use.
  model::HessianAssembly& hessian_assembly();
  // K0, the Hessian at rest, on the assembly's pattern.
  const SparseMatrix& rest_stiffness();
  // out = D z = alpha M z + beta K0 z.
  void damping_product(const VecX& z, VecX& out);
  // True when every node has the same mass on all its axes and is fixed on all axes or none: a per-node matrix
  // then serves every axis (the Kronecker form of local/global's and quasi-newton's prefactored matrices).
  bool axes_alike() const;
  // Sets the fixed DOFs of z to their positions now (prescribed, else rest).
  void apply_prescribed(VecX& z) const;
  // Explicit stability limit, s (Simulator::stable_time_step), cached until the fixed DOFs change.
  double stable_dt();
  // Ends a step at positions y: v = (y - x) / dt (or 0 when dt is 0, a quasi-static step), x = y.
  void advance(const VecX& y, double dt) {
    if (dt > 0.0)
      v = (y - x) / dt;
    else
      v.setZero();
    x = y;
    gradient_valid = false;
    fixed_grad_valid = false;
  }
  // The fixed DOFs changed.
  void refix() { m_stable_dt = -1.0; }

 private:
  std::unique_ptr<model::HessianAssembly> m_assembly;
  SparseMatrix m_k0;
  double m_stable_dt = -1.0;
};

}  // namespace hooke::solve::detail
