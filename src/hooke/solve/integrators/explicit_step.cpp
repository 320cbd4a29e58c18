// The explicit family: symplectic Euler and velocity Verlet.
#include <hooke/solve/detail/integrator_step.hpp>

namespace hooke::solve::detail {
namespace {

class ExplicitStep final : public IntegratorStep {
 public:
  ExplicitStep(const SimulationState& s, bool verlet) : m_verlet(verlet) {
    for (VecX* w : {&m_acc, &m_damping, &m_target}) w->setZero(s.nd);
  }

  // Symplectic Euler: v += dt a(x, v); x += dt v. Velocity Verlet: half kick, drift, half kick.
  StepReport step(SimulationState& s, double dt) override {
    StepReport r;
    r.beyond_stable_dt = dt > s.stable_dt();
    m_target = s.x;
    s.apply_prescribed(m_target);  // targets of the fixed DOFs
    acceleration(s, s.v);
    s.v += (m_verlet ? 0.5 : 1.0) * dt * m_acc;
    for (Eigen::Index i = 0; i < s.nd; ++i)  // drift; fixed DOFs move to their targets
      if (s.fixed(i)) {
        s.v(i) = (m_target(i) - s.x(i)) / dt;
        s.x(i) = m_target(i);
      } else {
        s.x(i) += dt * s.v(i);
      }
    s.gradient_valid = false;
    if (m_verlet) {
      acceleration(s, s.v);
      s.v += 0.5 * dt * m_acc;
    }
    return r;
  }

 private:
  // acc = M^-1 (f - dE/dx(x) - D w) on the free DOFs, 0 on the fixed ones.
  void acceleration(SimulationState& s, const VecX& w) {
    if (!s.gradient_valid) {
      s.model().gradient(s.x, s.grad, s.problem.interaction_or_null());
      s.gradient_valid = true;
    }
    m_acc = s.f_total - s.grad;
    if (s.damped()) {
      s.damping_product(w, m_damping);
      m_acc -= m_damping;
    }
    for (Eigen::Index i = 0; i < s.nd; ++i) m_acc(i) = s.fixed(i) ? 0.0 : m_acc(i) / s.dyn.mass(i);
  }

  bool m_verlet;
  VecX m_acc, m_damping, m_target;
};

}  // namespace

std::unique_ptr<IntegratorStep> make_explicit_step(const SimulationState& s, bool verlet) {
  return std::make_unique<ExplicitStep>(s, verlet);
}

}  // namespace hooke::solve::detail
