#include <charconv>
#include <hooke/core/error.hpp>
#include <hooke/core/settings.hpp>
#include <hooke/solve/dynamics_setup.hpp>
#include <hooke/solve/simulator_settings.hpp>

namespace hooke::solve {
namespace {

using settings::number_text;

const SimulatorField kSimulatorFields[] = {
    {"integrator",
     "quasi-newton (every model at a fixed budget per step, the real-time default), implicit-euler (Newton to "
     "convergence), implicit-euler-linearised (one Newton iteration, Baraff & Witkin), local-global (springs only; "
     "chebyshev: see docs/simulation.md for its measured error), symplectic-euler, velocity-verlet, quasi-static",
     [](SimulatorOptions& o, std::string_view t) { o.integrator = integrator_from_name(t); },
     [](const SimulatorOptions& o) { return std::string(integrator_name(o.integrator)); }},
    {"qn-iterations", "quasi-newton: L-BFGS iterations per step at most (the budget)",
     [](SimulatorOptions& o, std::string_view t) {
       o.quasi_newton.max_iterations = setting_integer("qn-iterations", t);
     },
     [](const SimulatorOptions& o) { return std::to_string(o.quasi_newton.max_iterations); }},
    {"qn-tolerance", "quasi-newton: |residual| / force scale to stop a step",
     [](SimulatorOptions& o, std::string_view t) { o.quasi_newton.tolerance = setting_number("qn-tolerance", t); },
     [](const SimulatorOptions& o) { return number_text(o.quasi_newton.tolerance); }},
    {"qn-hessian",
     "quasi-newton: initial Hessian, rest (the Newton matrix at rest), isotropic (a per-node factor, 3x cheaper to "
     "solve, more iterations) or auto (rest where the model's Hessian is exact, isotropic for the surface model's "
     "approximate one)",
     [](SimulatorOptions& o, std::string_view t) {
       o.quasi_newton.initial_hessian = quasi_newton_hessian_from_name(t);
     },
     [](const SimulatorOptions& o) { return std::string(quasi_newton_hessian_name(o.quasi_newton.initial_hessian)); }},
    {"linear-solver", "Newton steps: cholesky or cg",
     [](SimulatorOptions& o, std::string_view t) { o.newton.linear_solver = newton_linear_solver_from_name(t); },
     [](const SimulatorOptions& o) { return std::string(newton_linear_solver_name(o.newton.linear_solver)); }},
    {"cg-tolerance", "cg: relative residual of the linear solves (implicit-euler-linearised: the whole step's)",
     [](SimulatorOptions& o, std::string_view t) { o.newton.cg_tolerance = setting_number("cg-tolerance", t); },
     [](const SimulatorOptions& o) { return number_text(o.newton.cg_tolerance); }},
    {"newton-tolerance", "implicit-euler, quasi-static: |residual| / force scale to stop Newton",
     [](SimulatorOptions& o, std::string_view t) { o.newton.tolerance = setting_number("newton-tolerance", t); },
     [](const SimulatorOptions& o) { return number_text(o.newton.tolerance); }},
    {"newton-iterations", "implicit-euler, quasi-static: Newton iterations per step at most",
     [](SimulatorOptions& o, std::string_view t) { o.newton.max_iterations = setting_integer("newton-iterations", t); },
     [](const SimulatorOptions& o) { return std::to_string(o.newton.max_iterations); }},
    {"global-solve",
     "local-global: chebyshev (Chebyshev-accelerated Jacobi; measured 1.6e-3 of the largest displacement off a "
     "converged step on the 1 089-node cylinder and 2.6e-2 on the 11 425-node one, above the 1e-2 of the real-time "
     "path: lloyd-tet at nu 0.45, 300 steps, hooke bench) or direct (prefactored Cholesky, 2.6e-5 on 1 089)",
     [](SimulatorOptions& o, std::string_view t) { o.global_solve = global_solve_from_name(t); },
     [](const SimulatorOptions& o) { return std::string(global_solve_name(o.global_solve)); }},
    {"iterations", "local-global: iterations per step",
     [](SimulatorOptions& o, std::string_view t) { o.local_global_iterations = setting_integer("iterations", t); },
     [](const SimulatorOptions& o) { return std::to_string(o.local_global_iterations); }},
};

}  // namespace

std::span<const SimulatorField> simulator_fields() { return kSimulatorFields; }

bool set_simulator_field(SimulatorOptions& options, std::string_view name, std::string_view text) {
  for (const SimulatorField& f : kSimulatorFields)
    if (f.name == name) {
      f.set(options, text);
      return true;
    }
  return false;
}

int setting_integer(std::string_view name, std::string_view text) {
  return settings::parse_integer("set " + std::string(name), text);
}

}  // namespace hooke::solve
