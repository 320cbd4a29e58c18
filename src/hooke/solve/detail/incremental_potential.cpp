#include <cmath>
#include <hooke/solve/detail/incremental_potential.hpp>
#include <hooke/solve/detail/sparse_ops.hpp>

namespace hooke::solve::detail {

IncrementalPotential::IncrementalPotential(SimulationState& s) : m_s(s) {
  const VecX& rest = s.model().rest_positions();
  m_size = std::max(rest.maxCoeff() - rest.minCoeff(), 1e-300);
  for (VecX* w : {&m_x_n, &m_x_hat, &m_dz, &m_damping, &m_fixed_gradient}) w->setZero(s.nd);
}

void IncrementalPotential::begin(double w, double dt) {
  m_w = w;
  m_dt = dt;
  m_x_n = m_s.x;
  m_x_hat = m_s.x + dt * m_s.v;
  m_s.apply_prescribed(m_x_hat);
  double load = 0.0;
  for (Eigen::Index i = 0; i < m_s.nd; ++i)
    if (!m_s.fixed(i)) load += m_s.f_total(i) * m_s.f_total(i);
  m_load = std::sqrt(load);
  m_scale = -1.0;
  if (m_s.damped() && m_s.dyn.stiffness_damping > 0.0) m_s.rest_stiffness();  // before the assembly is refilled
}

double IncrementalPotential::value(const VecX& z) { return potential(z, m_s.model().energy(z)); }

void IncrementalPotential::gradient(const VecX& z, VecX& out) {
  m_s.model().gradient(z, out, m_s.problem.interaction_or_null());
  finish_gradient(z, out);
}

double IncrementalPotential::value_and_gradient(const VecX& z, VecX& out) {
  const double e = m_s.model().energy_and_gradient(z, out, m_s.problem.interaction_or_null());
  finish_gradient(z, out);
  return potential(z, e);
}

double IncrementalPotential::potential(const VecX& z, double e) {
  if (!std::isfinite(e)) return e;
  double phi = e - m_s.f_total.dot(z - m_s.model().rest_positions());
  if (m_w > 0.0) phi += 0.5 * m_w * (z - m_x_hat).cwiseAbs2().dot(m_s.dyn.mass);
  if (m_s.damped() && m_dt > 0.0) {
    m_dz = z - m_x_n;
    m_s.damping_product(m_dz, m_damping);
    phi += 0.5 / m_dt * m_dz.dot(m_damping);
  }
  return phi;
}

void IncrementalPotential::finish_gradient(const VecX& z, VecX& out) {
  for (Eigen::Index i = 0; i < m_s.nd; ++i) m_fixed_gradient(i) = m_s.fixed(i) ? out(i) : 0.0;
  out -= m_s.f_total;
  if (m_w > 0.0) out += m_w * m_s.dyn.mass.cwiseProduct(z - m_x_hat);
  if (m_s.damped() && m_dt > 0.0) {
    m_dz = z - m_x_n;
    m_s.damping_product(m_dz, m_damping);
    out += m_damping / m_dt;
  }
  for (Eigen::Index i = 0; i < m_s.nd; ++i)
    if (m_s.fixed(i)) out(i) = 0.0;
  if (m_scale < 0.0) m_scale = m_load + out.norm() + 1e-30;
}

SparseMatrix& IncrementalPotential::newton_matrix(const VecX& z, bool project) {
  model::HessianAssembly& a = m_s.hessian_assembly();
  const bool stiffness_damping = m_dt > 0.0 && m_s.dyn.stiffness_damping > 0.0;
  if (stiffness_damping) m_s.rest_stiffness();  // before `a` is overwritten
  a.assemble(z, project, m_s.problem.interaction_or_null());
  double* values = a.matrix().valuePtr();
  if (stiffness_damping) {
    const double* k = m_s.rest_stiffness().valuePtr();
    for (Eigen::Index q = 0; q < a.matrix().nonZeros(); ++q) values[q] += m_s.dyn.stiffness_damping / m_dt * k[q];
  }
  const double mass_factor = m_w + (m_dt > 0.0 ? m_s.dyn.mass_damping / m_dt : 0.0);
  for (Eigen::Index i = 0; i < m_s.nd; ++i)
    values[a.diagonal()[static_cast<size_t>(i)]] += mass_factor * m_s.dyn.mass(i);
  m_constraint.apply(a.matrix(), m_s.problem.fixed_dofs, 1);
  return a.matrix();
}

}  // namespace hooke::solve::detail
