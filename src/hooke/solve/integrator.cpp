#include <hooke/core/error.hpp>
#include <hooke/core/name_table.hpp>
#include <hooke/solve/detail/integrator_step.hpp>
#include <hooke/solve/integrator.hpp>
#include <string>

namespace hooke::solve {
namespace {

constexpr NameTable<Integrator, 7> kIntegrators{"integrator",
                                                {{{Integrator::kQuasiNewton, "quasi-newton"},
                                                  {Integrator::kImplicitEuler, "implicit-euler"},
                                                  {Integrator::kLocalGlobal, "local-global"},
                                                  {Integrator::kSymplecticEuler, "symplectic-euler"},
                                                  {Integrator::kVelocityVerlet, "velocity-verlet"},
                                                  {Integrator::kImplicitEulerLinearised, "implicit-euler-linearised"},
                                                  {Integrator::kQuasiStatic, "quasi-static"}}}};
constexpr NameTable<GlobalSolve, 2> kGlobalSolves{
    "global solve", {{{GlobalSolve::kDirect, "direct"}, {GlobalSolve::kChebyshev, "chebyshev"}}}};
constexpr NameTable<QuasiNewtonHessian, 3> kHessians{"quasi-newton initial Hessian",
                                                     {{{QuasiNewtonHessian::kAuto, "auto"},
                                                       {QuasiNewtonHessian::kRest, "rest"},
                                                       {QuasiNewtonHessian::kIsotropic, "isotropic"}}}};

}  // namespace

Integrator integrator_from_name(std::string_view name) { return kIntegrators.from_name(name); }
std::string_view integrator_name(Integrator integrator) { return kIntegrators.name(integrator); }
std::vector<std::string_view> integrator_names() { return kIntegrators.names(); }
GlobalSolve global_solve_from_name(std::string_view name) { return kGlobalSolves.from_name(name); }
std::string_view global_solve_name(GlobalSolve solve) { return kGlobalSolves.name(solve); }
QuasiNewtonHessian quasi_newton_hessian_from_name(std::string_view name) { return kHessians.from_name(name); }
std::string_view quasi_newton_hessian_name(QuasiNewtonHessian hessian) { return kHessians.name(hessian); }

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
