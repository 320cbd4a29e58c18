#pragma once
/// Time integrators of the Simulator, by stable name (shared by the library, the CLI and reports). Each family
/// lives in one file under solve/integrators/ behind detail::IntegratorStep; adding one touches this header, the
/// factory in integrator.cpp, its own file and the library's source list.
#include <hooke/solve/newton.hpp>
#include <string_view>
#include <vector>

namespace hooke::solve {

enum class Integrator {
  kSymplecticEuler,  ///< "symplectic-euler": v += dt M^-1 f(x, v); x += dt v. First order, explicit; stable
                     ///< for dt < 2 / omega_max (Simulator::stable_time_step); conserves energy up to a bounded
                     ///< oscillation (symplectic).
  kVelocityVerlet,   ///< "velocity-verlet": half kick, drift, half kick. Second order, explicit, same limit as
                     ///< symplectic Euler, symplectic (bounded energy error).
  kImplicitEuler,    ///< "implicit-euler": backward Euler, x_{n+1} minimises the incremental potential
                     ///< |x - x_n - dt v_n|^2_M / (2 dt^2) + E(x) - f.x (+ damping), by Newton's method with line
                     ///< search. First order; unconditionally stable; dissipates energy (numerical damping).
  kLocalGlobal,      ///< "local-global": Liu, Bargteil, O'Brien, Kavan 2013, "Fast Simulation of Mass-Spring
                     ///< Systems": the same incremental potential for spring-only models, solved by alternating
                     ///< spring directions (local) and one prefactored linear solve (global). Stable for any dt;
                     ///< a fixed iteration count trades accuracy for speed.
  kQuasiStatic,      ///< "quasi-static": each step relaxes to the static equilibrium under the current loads
                     ///< (Newton from the previous state); velocities are zero.
  kImplicitEulerLinearised,  ///< "implicit-euler-linearised": Baraff & Witkin 1998, "Large Steps in Cloth
                             ///< Simulation": backward Euler linearised about x_n, one linear solve
                             ///< (M + dt D + dt^2 K(x_n)) dv = dt (f(x_n) - D v_n - dt K(x_n) v_n) per step, i.e. one
                             ///< Newton iteration of implicit-euler from x_n without line search. Stable for stiff
                             ///< springs at large dt, one factorisation per step; the step is not iterated to
                             ///< convergence (StepReport::residual says how far it is; converged is true by
                             ///< definition).
  kQuasiNewton  ///< "quasi-newton": Liu, Bouaziz & Kavan 2017, "Quasi-Newton Methods for Real-Time Simulation of
                ///< Hyperelastic Materials": implicit-euler's incremental potential for any model, minimised by
                ///< L-BFGS with line search whose initial Hessian is the step's Newton matrix at rest, factorised
                ///< once per dt (grabbing nodes adds a capacitance correction, no refactorisation). One gradient,
                ///< one energy and one prefactored solve per iteration, up to QuasiNewtonOptions::max_iterations
                ///< (the real-time budget); StepReport::converged says whether the tolerance was met within it.
};

Integrator integrator_from_name(std::string_view name);  ///< @throws InvalidArgument listing the names
std::string_view integrator_name(Integrator integrator);
/// Every integrator's name, the real-time default (quasi-newton) first.
std::vector<std::string_view> integrator_names();

/// How local-global solves its global linear system each iteration.
enum class GlobalSolve {
  kDirect,    ///< "direct": one prefactored sparse Cholesky solve (Liu et al. 2013): each iteration is exact
  kChebyshev  ///< "chebyshev": one Jacobi sweep per iteration, accelerated by Chebyshev's semi-iterative method
              ///< (Wang 2015, "A Chebyshev Semi-Iterative Approach for Accelerating Projective and Position-based
              ///< Dynamics"): O(springs) per iteration, no factorisation; information travels a few springs per
              ///< iteration, so large meshes need more iterations (or steps) to reach the same state
};

GlobalSolve global_solve_from_name(std::string_view name);  ///< @throws InvalidArgument
std::string_view global_solve_name(GlobalSolve solve);      ///< "direct" or "chebyshev"

/// The initial Hessian of the quasi-newton integrator's L-BFGS.
enum class QuasiNewtonHessian {
  kRest,       ///< "rest": the step's Newton matrix at rest, M (1/dt^2 + alpha/dt) + (1 + beta/dt) K0
  kIsotropic,  ///< "isotropic": the same with each node pair's block of K0 replaced by a multiple of the identity
               ///< (its trace x isotropic_scale / dim): one per-node factor for all axes, dim x cheaper to solve
  kAuto        ///< "auto": rest where the model's Hessian is exact, isotropic where it only approximates the Jacobian
         ///< (Model::exact_hessian false: the surface model's blended anchors, whose force has no direction at rest,
         ///< and its volume penalty without the rank-one term). Measured on CGAL's femur surface model (scheme D,
         ///< E 1 MPa, gravity): rest stalls at step 5 (no descent after 5 iterations), isotropic runs 300 steps at
         ///< 2.05 iterations per step
};

QuasiNewtonHessian quasi_newton_hessian_from_name(std::string_view name);  ///< @throws InvalidArgument
std::string_view quasi_newton_hessian_name(QuasiNewtonHessian hessian);    ///< "auto", "rest" or "isotropic"

}  // namespace hooke::solve
