#pragma once
/// Data-driven identification of spring models (Lloyd et al. 2007, Sec. 2): the parameters theta that make a
/// mass-spring model reproduce reference deformations, by the linear least-squares force objective of Eq. 2 or
/// the node-distance objective of Eq. 1 (see docs/methods/identification.md).
#include <hooke/calibrate/spring_model.hpp>
#include <hooke/identify/bounded_least_squares.hpp>
#include <hooke/identify/parameter_layout.hpp>
#include <hooke/identify/reference_case.hpp>
#include <hooke/mesh/mesh.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <optional>
#include <string_view>
#include <vector>

namespace hooke::identify {

/// Stable names: "forces", "positions".
enum class Objective {
  kForces,    ///< Eq. 2: min |f_ref - U(p_ref) theta| over theta >= 0, one sparse bounded least-squares solve
  kPositions  ///< Eq. 1: min sum_c |x_c(theta) - p_ref,c|^2 with x_c the model's equilibrium, from the Eq. 2 fit
};
Objective objective_from_name(std::string_view name);  ///< @throws InvalidArgument listing the names
std::string_view objective_name(Objective objective);

struct IdentifyOptions {
  Parameters parameters = Parameters::kSprings;  ///< what is fitted, default springs
  Objective objective = Objective::kPositions;   ///< default positions (Eq. 1 from the Eq. 2 fit)
  /// Weight w of the penalty toward the mean stiffness that Lloyd et al. suggest (Sec. 2): w^2 c^2 |theta_g -
  /// mean(theta_g)|^2 for the springs and for the volume terms, c the RMS column norm of U in the group, so w is
  /// dimensionless (w = 1 pulls as hard as one typical data row). Default 0 (none).
  double regularization = 0.0;
  /// Every spring keeps at least this fraction of the mean k: start_model's when given, else a rough first fit's (a
  /// spring at k = 0 can leave a mechanism, which has no equilibrium); 0 allows k = 0. Default 1e-3.
  double stiffness_floor = 1e-3;
  /// Volume terms may be negative (ParameterLayout::negative_volume): needed to reach a reference with nu < 1/4.
  /// Eq. 1 rejects any step whose model has no stable equilibrium on a training case. Default false (k_V >= 0).
  bool negative_volume = false;
  BoundedLeastSquaresOptions least_squares;  ///< the Eq. 2 solver (tolerance 1e-9 relative; must be in (0, 1))
  int position_iterations = 30;              ///< positions: projected-gradient iterations at most, default 30
  /// positions: stop when the relative projected gradient falls below this, default 1e-6
  double position_tolerance = 1e-6;
  /// A start, e.g. an analytic model (its k and k_V on the layout, kept within the bounds). Eq. 2 starts from it
  /// (not with rest lengths); Eq. 1 starts from whichever of it and the Eq. 2 fit has the smaller G. None by default.
  std::optional<calibrate::SpringModel> start_model;
  /// positions: the static solves (defaults; stability checks off, a warm start from the previous equilibrium)
  solve::StaticOptions statics;
};

struct IdentifyReport {
  double force_residual = 0.0;              ///< |f_ref - U theta| / |f_ref| over the training cases' free DOFs
  BoundedLeastSquaresReport least_squares;  ///< the Eq. 2 solve (the last one with rest lengths)
  int clamped_rest_lengths = 0;             ///< springs whose fitted l0 fell outside [L/2, 2L] (rest-length only)
  int position_iterations = 0;              ///< positions: iterations done
  int static_solves = 0;                    ///< positions: equilibria computed
  /// positions: G / G_ref per iteration, G = sum_c |x_c - p_ref,c|^2, G_ref = sum_c |p_ref,c - X|^2 (the first
  /// entry is the start's)
  double eq2_positions_objective = 0.0;  ///< positions: G / G_ref of the Eq. 2 fit
  double start_model_objective = 0.0;    ///< positions: G / G_ref of start_model (0 without one)
  bool started_from_model = false;       ///< positions: Eq. 1 started from start_model
  std::vector<double> position_history;
  bool converged = false;      ///< the objective's own test was met
  double min_stiffness = 0.0;  ///< smallest identified spring k, N/m
  double max_stiffness = 0.0;  ///< largest identified spring k, N/m
  double scale_factor = 0.0;   ///< scale: the fitted factor c on the start model (0 for the other parameters)
  double seconds = 0.0;        ///< wall time
};

/// An identified model: the unknowns, their values and the spring model they make.
struct Identification {
  ParameterLayout layout;          ///< with the fitted rest lengths when they were identified
  VecX theta;                      ///< on `layout` (no offsets: they are folded into the rest lengths)
  calibrate::SpringModel springs;  ///< what theta makes (spring_model)
  IdentifyReport report;
};

/// Checks the ranges of `options`: the Eq. 2 tolerance in (0, 1), the regularization weight >= 0, the stiffness
/// floor in [0, 1), the Eq. 1 iterations >= 0 (identify() calls it; front ends call it before building references).
/// @throws InvalidArgument naming the option and its value
void validate_options(const IdentifyOptions& options);

/// Identifies a spring model on `mesh` from the cases not held out. Forces: Eq. 2 as a bounded least-squares
/// problem with the rows of every training case's free DOFs, every k >= stiffness_floor x the mean k; with rest
/// lengths, the fitted l0 are then fixed and k,
/// k_V fitted again, so that the model is exactly the one measured. Positions: Eq. 1 from there by projected
/// gradients with the Barzilai-Borwein step, the gradient by the adjoint of each equilibrium (PositionsObjective).
/// @param mesh   validated tet or triangle mesh, m
/// @param cases  reference cases on mesh's nodes (validate_reference), at least one not held out; the rest state
///               (no load, no support) is added as a case with rest lengths
/// @throws InvalidArgument for bad cases or options out of range (validate_options); SolverFailure when an Eq. 1
/// start has no equilibrium
Identification identify(const mesh::Mesh& mesh, const std::vector<ReferenceCase>& cases,
                        const IdentifyOptions& options = {});

/// |f_ref - dE/dx(p_ref)| / |f_ref| over the free DOFs of `cases` for the spring model of theta on `layout`.
double force_residual(const ParameterLayout& layout, const VecX& theta, const std::vector<ReferenceCase>& cases);

}  // namespace hooke::identify
