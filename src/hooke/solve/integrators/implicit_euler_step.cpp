// The implicit Euler family: backward Euler iterated to convergence (implicit-euler) and linearised to one Newton
// iteration (implicit-euler-linearised, Baraff & Witkin 1998), both on the Newton core.
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/solve/detail/incremental_potential.hpp>
#include <hooke/solve/detail/integrator_step.hpp>

namespace hooke::solve::detail {
namespace {

class ImplicitEulerStep final : public IntegratorStep {
 public:
  ImplicitEulerStep(SimulationState& s, const NewtonOptions& newton, bool linearised)
      : m_objective(s), m_newton(newton), m_linearised(linearised) {
    for (VecX* w : {&m_y, &m_grad, &m_delta}) w->setZero(s.nd);
  }

  StepReport step(SimulationState& s, double dt) override {
    if (dt != m_dt) m_newton.invalidate();  // the Newton matrix holds M / dt^2
    m_dt = dt;
    m_objective.begin(1.0 / (dt * dt), dt);
    const StepReport r = m_linearised ? linearised(s) : converged(s);
    s.advance(m_y, dt);
    return r;
  }
  void refix() override { m_newton.invalidate(); }
  long linear_iterations() const override { return m_newton.linear_iterations(); }

 private:
  // Newton from x_hat (or from x where x_hat is inadmissible) to the minimiser of the incremental potential.
  StepReport converged(SimulationState& s) {
    m_y = m_objective.inertial_target();
    if (!std::isfinite(s.model().energy(m_y))) {
      m_y = s.x;
      s.apply_prescribed(m_y);
    }
    return step_report(m_newton.solve(m_objective, m_y));
  }

  // Baraff & Witkin 1998: one Newton iteration of the incremental potential from y = x_n (fixed DOFs at their
  // targets), i.e. (M + dt D + dt^2 K(x_n)) dv = dt (f - grad E(x_n) - D v_n - dt K(x_n) v_n), no line search.
  StepReport linearised(SimulationState& s) {
    m_y = s.x;
    s.apply_prescribed(m_y);
    m_objective.gradient(m_y, m_grad);
    if (!m_newton.direction(m_objective, m_y, m_grad, m_newton.options().cg_tolerance, m_delta))
      throw SolverFailure("the Newton matrix of the time step is not positive definite even with a shift");
    m_y += m_delta;
    StepReport r;
    r.iterations = 1;
    m_objective.gradient(m_y, m_grad);
    r.residual = m_grad.norm();  // what the one iteration leaves of the implicit step's equations
    return r;
  }

  IncrementalPotential m_objective;
  NewtonSolver m_newton;
  bool m_linearised;
  double m_dt = -1.0;
  VecX m_y, m_grad, m_delta;
};

}  // namespace

std::unique_ptr<IntegratorStep> make_implicit_euler_step(SimulationState& s, const NewtonOptions& newton,
                                                         bool linearised) {
  return std::make_unique<ImplicitEulerStep>(s, newton, linearised);
}

}  // namespace hooke::solve::detail
