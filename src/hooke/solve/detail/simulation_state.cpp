#include <cmath>
#include <hooke/solve/detail/simulation_state.hpp>
#include <hooke/solve/detail/sparse_ops.hpp>
#include <limits>

namespace hooke::solve::detail {

SimulationState::SimulationState(model::Problem p, Dynamics d)
    : problem(std::move(p)), dyn(std::move(d)), nd(problem.model->dof_count()) {
  for (VecX* w : {&x, &v, &f_total, &grad, &fixed_grad}) w->setZero(nd);
}

model::HessianAssembly& SimulationState::hessian_assembly() {
  if (!m_assembly) m_assembly = std::make_unique<model::HessianAssembly>(model());
  return *m_assembly;
}

const SparseMatrix& SimulationState::rest_stiffness() {
  if (m_k0.rows() == 0) {
    hessian_assembly().assemble(model().rest_positions(), false);
    m_k0 = m_assembly->matrix();
  }
  return m_k0;
}

void SimulationState::damping_product(const VecX& z, VecX& out) {
  if (dyn.stiffness_damping > 0.0) {
    multiply(rest_stiffness(), z, out);
    out *= dyn.stiffness_damping;
  } else {
    out.setZero();
  }
  if (dyn.mass_damping > 0.0) out += dyn.mass_damping * dyn.mass.cwiseProduct(z);
}

bool SimulationState::axes_alike() const {
  const int d = model().dim();
  for (Eigen::Index i = 0; i < nd; ++i)
    if (dyn.mass(i) != dyn.mass(i - i % d) || fixed(i) != fixed(i - i % d)) return false;
  return true;
}

void SimulationState::apply_prescribed(VecX& z) const {
  const bool given = problem.prescribed_positions.size() == z.size();
  for (Eigen::Index i = 0; i < nd; ++i)
    if (fixed(i)) z(i) = given ? problem.prescribed_positions(i) : model().rest_positions()(i);
}

double SimulationState::stable_dt() {
  if (m_stable_dt >= 0.0) return m_stable_dt;
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
  if (!(lambda > 0.0)) return m_stable_dt = std::numeric_limits<double>::infinity();
  // Central differences with Rayleigh damping of ratio zeta = (alpha / omega + beta omega) / 2 at the highest
  // frequency are stable for omega dt <= 2 (sqrt(1 + zeta^2) - zeta) (e.g. Belytschko et al., Nonlinear
  // Finite Elements, Sec. 6.2); zeta = 0 gives 2 / omega.
  const double omega = std::sqrt(lambda);
  const double zeta = 0.5 * (dyn.mass_damping / omega + dyn.stiffness_damping * omega);
  return m_stable_dt = 2.0 / omega * (std::sqrt(1.0 + zeta * zeta) - zeta);
}

}  // namespace hooke::solve::detail
