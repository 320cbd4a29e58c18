#pragma once
/// The large-strain term law of a spring model fitted to a hyperelastic FEM by measurement: the Seth-Hill exponents
/// of its springs and volume terms (calibrate::SpringModel::spring_exponent, volume_exponent) that bring its
/// displacement-controlled stretch, compression and shear closest to the FEM of a law up to a strain. The stiffness
/// at rest (Lloyd et al. 2007, Eq. 8-14 and the per-element fits) is not touched. docs/methods/large_strain.md.
#include <hooke/calibrate/calibrated_model.hpp>
#include <hooke/material/material.hpp>
#include <hooke/model/load_case.hpp>
#include <string>
#include <vector>

namespace hooke::experiments {

struct TermLawFitOptions {
  material::Law law = material::Law::kNeoHookean;  ///< the FEM law the model is fitted to
  double strain_range = 0.2;                       ///< S: fitted on the cases at S/2 and S (> 0, <= 0.5)
  /// the load cases, each under displacement control (the top moved by strain x height)
  std::vector<model::LoadKind> loads = {model::LoadKind::kStretch, model::LoadKind::kCompress, model::LoadKind::kShear};
  /// The pattern search's step sizes after the grid: 1/2, 1/4, ... (3: down to 1/8; 0: the grid alone), >= 0.
  int refinements = 3;
};

/// What the fit found.
struct TermLawFit {
  double spring_exponent = 1.0;  ///< m
  double volume_exponent = 1.0;  ///< q
  /// the worst case of the fit: max over the cases of max(relative L2 of the displacement, force error) at (m, q)
  double worst_error = 0.0;
  double hookean_error = 0.0;  ///< the same for m = q = 1 (today's Hookean springs and quadratic volume terms)
  int evaluations = 0;         ///< (m, q) pairs solved
  std::string summary;         ///< one line for reports and the model's choice text
};

/// The worst error (as TermLawFit::worst_error) of `model` with its own exponents against the FEM cases of `options`
/// (+infinity where the model has no stable equilibrium on a case).
/// @throws InvalidArgument as fit_term_law; SolverFailure when the FEM itself has no stable equilibrium
double term_law_error(const calibrate::CalibratedModel& model, const TermLawFitOptions& options);

/// Fits (m, q) of a springs model (a calibration method's, or a file's springs and volume terms) on its own mesh and
/// material: the FEM references are solved once; a coarse grid of (m, q) is measured (m in {1, 0, -1}, q in
/// {1, 0, -1, -2}; for St. Venant-Kirchhoff m in {3, 2, 1}, q in {2, 1, 0, -1}), then a pattern search refines the best
/// to 1/8 (options.refinements) (m in [-4, 4], q in [-6, 4]). Returns the pair of least worst error; it is never worse
/// than m = q = 1, which is always measured.
/// @throws InvalidArgument for a surface or FEM model, a 2D model without springs, or a strain outside (0, 0.5];
///   SolverFailure when the FEM has no stable equilibrium on a case (the law cannot reach that strain)
TermLawFit fit_term_law(const calibrate::CalibratedModel& model, const TermLawFitOptions& options);

/// fit_term_law applied: `model` with the fitted exponents, and its choice text extended by the fit's summary.
calibrate::CalibratedModel with_fitted_law(calibrate::CalibratedModel model, const TermLawFitOptions& options);

/// `--method auto` over a strain range. `picked` is the small-strain pick (calibrate::calibrate_model with "auto", on a
/// tet or triangle mesh); the any-nu models of its element kind (any-nu-tet and stiffness-fit-volume for tets,
/// any-nu-triangle for triangles) are calibrated beside it on its mesh and material (linear, same density), each one's
/// law is fitted, and the model of least worst error is returned, its choice text naming every candidate's fitted and
/// Hookean worst errors.
/// @throws as fit_term_law
calibrate::CalibratedModel choose_for_range(const calibrate::CalibratedModel& picked, const TermLawFitOptions& options);

}  // namespace hooke::experiments
