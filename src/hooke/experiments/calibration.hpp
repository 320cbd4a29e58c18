#pragma once
/// Calibration as `hooke calibrate` and hooke.calibrate run it: the model factory's model, its term law fitted up to a
/// strain range when one is asked for, and its certificate against FEM, from one settings struct declared once
/// (docs/architecture.md, "Settings").
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/core/settings.hpp>
#include <hooke/material/material.hpp>
#include <span>

namespace hooke::experiments {

/// Everything a calibration takes besides the mesh and the material.
struct CalibrationSettings {
  calibrate::ModelOptions model;               ///< the model factory's options (calibrate::model_settings)
  material::Law law = material::Law::kLinear;  ///< the FEM law the model follows up to strain_range
  double strain_range = 0.0;                   ///< > 0: the term law fitted to `law` up to this strain
  int fit_refinements = 3;                     ///< the fit's pattern-search steps (TermLawFitOptions::refinements)
  bool certify = false;                        ///< measure the model against FEM and store the certificate
  double certify_strain = 0.01;                ///< the certificate's strain without a strain range
  int layers = 4;                              ///< the surface model's radial tet layers for the certificate
};

/// Every user-settable field of CalibrationSettings: calibrate::model_settings() first, then the range fit's and the
/// certificate's, in the order --help lists them.
std::span<const settings::Setting<CalibrationSettings>> calibration_settings();

/// The range fit and the certificate of `settings` applied to `model` (from the model factory or a model file):
/// with strain_range > 0 the term law fitted to settings.law (experiments::choose_for_range when `automatic`, i.e.
/// the method was "auto" on a mesh, else with_fitted_law); with certify, certify_range (a strain range) or certify.
/// @throws InvalidArgument for a law other than linear without a strain range, and as fit_term_law and certify
calibrate::CalibratedModel finish_calibration(calibrate::CalibratedModel model, const CalibrationSettings& settings,
                                              bool automatic);

/// calibrate::calibrate_model on `mesh` for `material` with settings.model, then finish_calibration (automatic for
/// method "auto" unless the surface model was picked).
/// @throws as calibrate_model and finish_calibration
calibrate::CalibratedModel calibrate_with(const mesh::Mesh& mesh, const material::Material& material,
                                          const CalibrationSettings& settings);

}  // namespace hooke::experiments
