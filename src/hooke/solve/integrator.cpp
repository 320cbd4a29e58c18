#include <hooke/core/error.hpp>
#include <hooke/solve/detail/integrator_step.hpp>
#include <hooke/solve/integrator.hpp>
#include <string>

namespace hooke::solve {
namespace {

constexpr std::string_view kNames[] = {"symplectic-euler", "velocity-verlet", "implicit-euler",
                                       "local-global",     "quasi-static",    "implicit-euler-linearised",
                                       "quasi-newton"};

}  // namespace

Integrator integrator_from_name(std::string_view name) {
  for (size_t i = 0; i < std::size(kNames); ++i)
    if (kNames[i] == name) return static_cast<Integrator>(i);
  throw InvalidArgument("unknown integrator '" + std::string(name) +
                        "' (use symplectic-euler, velocity-verlet, implicit-euler, implicit-euler-linearised, "
                        "local-global, quasi-newton, quasi-static)");
}

std::string_view integrator_name(Integrator integrator) { return kNames[static_cast<size_t>(integrator)]; }

GlobalSolve global_solve_from_name(std::string_view name) {
  if (name == "direct") return GlobalSolve::kDirect;
  if (name == "chebyshev") return GlobalSolve::kChebyshev;
  throw InvalidArgument("unknown global solve '" + std::string(name) + "' (use direct or chebyshev)");
}

QuasiNewtonHessian quasi_newton_hessian_from_name(std::string_view name) {
  if (name == "rest") return QuasiNewtonHessian::kRest;
  if (name == "isotropic") return QuasiNewtonHessian::kIsotropic;
  if (name == "auto") return QuasiNewtonHessian::kAuto;
  throw InvalidArgument("unknown quasi-newton initial Hessian '" + std::string(name) +
                        "' (use auto, rest or isotropic)");
}

namespace detail {

// Defined in solve/integrators/, one file per family.
std::unique_ptr<IntegratorStep> make_explicit_step(const SimulationState& s, bool verlet);
std::unique_ptr<IntegratorStep> make_implicit_euler_step(SimulationState& s, const NewtonOptions& newton,
                                                         bool linearised);
std::unique_ptr<IntegratorStep> make_quasi_static_step(SimulationState& s, const NewtonOptions& newton);
std::unique_ptr<IntegratorStep> make_local_global_step(SimulationState& s, const SimulatorOptions& options);
std::unique_ptr<IntegratorStep> make_quasi_newton_step(SimulationState& s, const SimulatorOptions& options);

std::unique_ptr<IntegratorStep> make_integrator_step(const SimulatorOptions& options, SimulationState& s) {
  switch (options.integrator) {
    case Integrator::kSymplecticEuler: return make_explicit_step(s, false);
    case Integrator::kVelocityVerlet: return make_explicit_step(s, true);
    case Integrator::kImplicitEuler: return make_implicit_euler_step(s, options.newton, false);
    case Integrator::kImplicitEulerLinearised: return make_implicit_euler_step(s, options.newton, true);
    case Integrator::kQuasiStatic: return make_quasi_static_step(s, options.newton);
    case Integrator::kLocalGlobal: return make_local_global_step(s, options);
    case Integrator::kQuasiNewton: return make_quasi_newton_step(s, options);
  }
  throw InvalidArgument("unknown integrator");
}

}  // namespace detail
}  // namespace hooke::solve
