// The quasi-static family: each step relaxes to the static equilibrium under the loads of its end (Newton from the
// previous state on the Newton core); velocities are zero.
#include <hooke/solve/detail/incremental_potential.hpp>
#include <hooke/solve/detail/integrator_step.hpp>

namespace hooke::solve::detail {
namespace {

class QuasiStaticStep final : public IntegratorStep {
 public:
  QuasiStaticStep(SimulationState& s, const NewtonOptions& newton) : m_objective(s), m_newton(newton) {
    m_y.setZero(s.nd);
  }

  StepReport step(SimulationState& s, double) override {
    m_objective.begin(0.0, 0.0);
    m_y = s.x;
    s.apply_prescribed(m_y);
    const StepReport r = step_report(m_newton.solve(m_objective, m_y));
    s.advance(m_y, 0.0);
    return r;
  }
  void refix() override { m_newton.invalidate(); }
  long linear_iterations() const override { return m_newton.linear_iterations(); }

 private:
  IncrementalPotential m_objective;
  NewtonSolver m_newton;
  VecX m_y;
};

}  // namespace

std::unique_ptr<IntegratorStep> make_quasi_static_step(SimulationState& s, const NewtonOptions& newton) {
  return std::make_unique<QuasiStaticStep>(s, newton);
}

}  // namespace hooke::solve::detail
