#pragma once
/// Identification as an experiment: reference deformations from hooke's FEM under load cases in every direction
/// (Lloyd et al. 2007, Sec. 2: "small stretching, compression and shear deformations in all directions"), the
/// fit of Eq. 1 or Eq. 2, and the identified model's error on training and held-out cases beside an analytic model's.
#include <filesystem>
#include <hooke/calibrate/calibrated_model.hpp>
#include <hooke/identify/identify.hpp>
#include <hooke/material/material.hpp>
#include <hooke/mesh/mesh.hpp>
#include <hooke/model/load_case.hpp>
#include <string>
#include <vector>

namespace hooke::experiments {

struct ReferenceLoads {
  /// each case's traction is scaled so that the linear FEM's largest node displacement is strain x the body's
  /// extent along the loaded axis; default 0.01
  double strain = 0.01;
  int held_out = 4;      ///< random cases (random direction, linearly varying traction) kept out of the fit, default 4
  unsigned seed = 2007;  ///< of the random cases
  /// kTraction (default): the loaded facets carry a traction. kDisplacement: their nodes are held by an instrument,
  /// moved by strain x extent x the case's direction field (ramped in the nonlinear solve), and the force it applies
  /// on each (the FEM's reaction dE/dx) is the case's measured force (identify::ReferenceCase::prescribed_dofs)
  model::LoadControl control = model::LoadControl::kTraction;
};

/// Reference cases from the FEM of `material` (its law: linear, or StVK / Neo-Hookean solved by Newton). Training:
/// for each axis a, the boundary facets at the low end of a (outward normal within 60 degrees of -a, centroid in
/// the lowest quarter of the extent) are clamped and a uniform traction acts on those at the high end, along +a
/// (stretch), -a (compress) and each other axis (shear): 12 cases on a tet mesh, 6 on a triangle mesh. Held out:
/// `held_out` cases on the same supports with a random direction and a traction varying linearly over the patch.
/// The linear FEM factorises once per support set. Under displacement control the same cases prescribe the loaded
/// nodes' displacement instead (the direction field of the traction), largest move strain x extent.
/// @param mesh      validated tet or triangle mesh, m
/// @param material  E (Pa), nu, thickness for 2D, law
/// @throws InvalidArgument when an end of an axis has no facets; SolverFailure when a nonlinear case fails
std::vector<identify::ReferenceCase> fem_reference_cases(const mesh::Mesh& mesh, const material::Material& material,
                                                         const ReferenceLoads& loads = {});

/// The defaults of `hooke identify` and hooke.identify on `mesh`: springs+volume on tets, springs on triangles.
identify::Parameters default_parameters(const mesh::Mesh& mesh);
/// The analytic model an identification is measured against (and starts Eq. 1 from): any-nu-tet on tets,
/// any-nu-triangle on triangles.
std::string default_analytic_method(const mesh::Mesh& mesh);

/// The identification options as `hooke identify` and hooke.identify name them, with their one set of defaults.
struct NamedIdentifyOptions {
  std::string parameters = "auto";      ///< identify::parameters_from_name, or "auto" (default_parameters)
  std::string objective = "positions";  ///< identify::objective_from_name
  double regularization = 0.0;          ///< IdentifyOptions::regularization
  double stiffness_floor = 1e-3;        ///< IdentifyOptions::stiffness_floor, in [0, 1)
  int iterations = 30;                  ///< IdentifyOptions::position_iterations
  double tolerance = 1e-9;              ///< the Eq. 2 solver's relative tolerance, in (0, 1)
  bool negative_volume = false;         ///< IdentifyOptions::negative_volume
};
/// The IdentifyOptions `named` stands for on `mesh`, range-checked (identify::validate_options).
/// @throws InvalidArgument for an unknown name or a value out of range
identify::IdentifyOptions identify_options(const NamedIdentifyOptions& named, const mesh::Mesh& mesh);

/// What `hooke identify` reports.
struct IdentificationStudy {
  identify::Identification identification;
  std::string analytic_method;            ///< the analytic model compared ("any-nu-tet" on tets)
  std::vector<std::string> case_names;    ///< per reference case
  std::vector<char> held_out;             ///< per case
  std::vector<double> identified_errors;  ///< per case: relative L2 |x - p_ref| / |p_ref - X| of the identified model
  std::vector<double> analytic_errors;    ///< the same for the analytic model
  /// per case under displacement control: the error of the total force on the prescribed nodes,
  /// identify::reaction_error (-1 for a case under forces)
  std::vector<double> identified_force_errors, analytic_force_errors;
  double training_error = 0.0;           ///< RMS over training cases of identified_errors
  double held_out_error = 0.0;           ///< RMS over held-out cases (0 when there are none)
  double analytic_training_error = 0.0;  ///< RMS of analytic_errors over the training cases
  double analytic_held_out_error = 0.0;  ///< RMS of analytic_errors over the held-out cases
  double analytic_force_residual = 0.0;  ///< Eq. 2's relative residual of the analytic model on the training cases
  double evaluation_seconds = 0.0;       ///< time of the equilibria of both models on every case
};

/// Identifies a model from `cases` and measures it and the analytic `analytic_method` model (calibrated from
/// `material`) on every case by static equilibrium (Newton). The analytic model is Eq. 1's second start
/// (IdentifyOptions::start_model) unless the options name one.
/// @param strain_range  > 0 with a nonlinear material.law: the analytic model is the large-strain one, its term law
///                      fitted to that law up to this strain (experiments::fit_term_law), so that a start exists at
///                      strains where Hookean springs have no stable equilibrium; the identified model keeps its law.
///                      0 (default): the analytic model's Hookean springs
/// @throws InvalidArgument for an unknown method or bad cases; SolverFailure from identify()
IdentificationStudy identification_study(const mesh::Mesh& mesh, const material::Material& material,
                                         const std::vector<identify::ReferenceCase>& cases,
                                         const identify::IdentifyOptions& options, const std::string& analytic_method,
                                         double strain_range = 0.0);

/// The identified model as a model file's contents (method "identified", its equation naming the objective, the
/// parameters and the number of cases), with lumped masses of `density` (kg/m^3) and the analytic model's errors
/// beside its own in the certificate-free warnings-free form that calibrate::write_model writes.
calibrate::CalibratedModel identified_model(const mesh::Mesh& mesh, const material::Material& material, double density,
                                            const IdentificationStudy& study, const identify::IdentifyOptions& options);

/// The study as JSON: options, per case name / held out / both errors, RMS errors, the least-squares and Eq. 1
/// iterations, the force residual, the k range and the times.
std::string identification_report_json(const IdentificationStudy& study, const identify::IdentifyOptions& options);

}  // namespace hooke::experiments
