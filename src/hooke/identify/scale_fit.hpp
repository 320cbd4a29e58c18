#pragma once
/// Lloyd et al. 2007, Eq. 1 with one unknown: the factor c that multiplies every spring stiffness k and volume
/// stiffness k_V of a given model so that its static equilibria come closest to the reference positions,
/// G(c) = sum over the training cases of |x_c(c) - p_c|^2. A linear model under forces with supports at rest
/// answers with u(c) = u(1) / c, so G has the closed-form minimiser c = sum |u|^2 / sum u . u_ref; the spring models
/// are nonlinear, so it is iterated from the current c with fresh equilibria until c changes by less than 1e-9.
/// Why one factor matters: the per-element fits (stiffness-fit) are too compliant by 8-39 % on irregular tets
/// (docs/methods/any_nu.md), a size error, not a shape error.
#include <hooke/calibrate/spring_model.hpp>
#include <hooke/identify/reference_case.hpp>
#include <hooke/mesh/mesh.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <vector>

namespace hooke::identify {

struct ScaleFit {
  double factor = 1.0;             ///< c, dimensionless (> 0)
  calibrate::SpringModel springs;  ///< the start model with k and k_V times c (rest lengths kept)
  std::vector<double> history;     ///< G / G_ref per iteration (the first: c = 1)
  int iterations = 0;              ///< fixed-point updates of c
  int static_solves = 0;           ///< equilibria computed
  bool converged = false;          ///< c changed by less than 1e-9 (relative) in the last update
};

/// Fits c on the cases not held out (at least one, with a non-zero reference displacement). Under displacement control
/// (training cases with prescribed DOFs: all of them or none) the equilibria do not depend on c and the forces on the
/// prescribed DOFs are c times those at c = 1: c is their least-squares fit to the measured forces, in one step, and
/// `history` holds sum |R(c) - R_ref|^2 / sum |R_ref|^2 at c = 1 and at the fit.
/// @param mesh     the rest mesh the model stands on, m
/// @param start    the model to scale (springs and volume terms on mesh's nodes)
/// @param cases    reference cases (validate_reference)
/// @param statics  options of the static solves
/// @throws InvalidArgument without a training case; SolverFailure when an equilibrium is not found or the model
///   moves against the reference (sum u . u_ref <= 0, no positive c fits)
ScaleFit fit_scale(const mesh::Mesh& mesh, const calibrate::SpringModel& start, const std::vector<ReferenceCase>& cases,
                   const solve::StaticOptions& statics = {}, int max_iterations = 10);

/// `springs` with every k and k_V multiplied by `factor` (> 0).
calibrate::SpringModel scaled(calibrate::SpringModel springs, double factor);

}  // namespace hooke::identify
