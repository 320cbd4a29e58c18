#pragma once
// The interface of one time integrator family (one file each under solve/integrators/), and the factory that
// picks one by Integrator (solve/integrator.cpp).
#include <hooke/solve/detail/simulation_state.hpp>
#include <hooke/solve/newton.hpp>
#include <memory>

namespace hooke::solve::detail {

class IntegratorStep {
 public:
  virtual ~IntegratorStep() = default;
  // Advances s.x and s.v by dt (s) from time t to t + dt; s.f_total and the fixed DOFs' targets are those of
  // t + dt. The report's probe_force and linear_iterations are filled by the Simulator. Allocates nothing after
  // the first call with the same dt (see Simulator::step).
  virtual StepReport step(SimulationState& s, double dt) = 0;
  // The fixed DOFs changed (a probe grabbed or let go): factorisations are redone at their next use.
  virtual void refix() {}
  // Conjugate-gradient iterations of the last step (0 where the integrator has none).
  virtual long linear_iterations() const { return 0; }
};

// A step's report from its Newton solve's.
inline StepReport step_report(const NewtonReport& newton) {
  StepReport r;
  r.iterations = newton.iterations;
  r.residual = newton.residual;
  r.converged = newton.converged;
  return r;
}

// The integrator `options.integrator`, set up for `s`.
// @throws InvalidArgument when the model does not suit it (local-global with non-spring blocks)
std::unique_ptr<IntegratorStep> make_integrator_step(const SimulatorOptions& options, SimulationState& s);

}  // namespace hooke::solve::detail
