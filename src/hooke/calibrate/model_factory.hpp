#pragma once
/// The one model factory: every front end (CLI, Python, viewer) gets its model from here, by method name or
/// from a model file, and never chooses term blocks itself (docs/architecture.md).
#include <hooke/calibrate/calibrated_model.hpp>
#include <hooke/calibrate/surface_model.hpp>
#include <hooke/mesh/tetrahedralize.hpp>
#include <hooke/model/model.hpp>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace hooke::calibrate {

struct ModelOptions {
  /// "auto" (the default: calibrate::choose_method picks by element kind and nu, from measured errors), a
  /// calibration method (method_from_name), "surface" (Arnab & Raja) or "fem" (the FEM model of `material.law`).
  std::string method = "auto";
  double density = 1000.0;  ///< kg/m^3 (> 0), for the lumped masses (and the surface model's object mass)
  SurfaceOptions surface;   ///< "surface" only; its density is replaced by `density`
  /// How a closed surface mesh is made into tets for every method but "surface" (mesh::tetrahedralize).
  mesh::TetrahedralizeOptions tetrahedralize;
  /// The spring methods' term law (SpringModel::spring_exponent, volume_exponent; docs/methods/large_strain.md):
  /// Seth-Hill exponents in [-8, 8], 1 (default) Hookean springs and quadratic volume terms.
  double spring_exponent = 1.0;
  double volume_exponent = 1.0;
  /// E and nu per element region (`--material REGION=E,NU`): every method's terms element by element with that
  /// element's material; the other regions take the material given to calibrate_model. Not for "surface".
  std::vector<RegionMaterial> regions;
};

/// Every name ModelOptions::method accepts: "auto", the calibration methods, then "surface" and "fem".
std::vector<std::string> model_method_names();

/// Where the constants of `method` come from, one line ("Lloyd et al. 2007, Eq. 12 with l-hat of Eq. 13").
/// @throws InvalidArgument for an unknown name
std::string method_equation(std::string_view method);

/// Calibrates the model named by options.method on `mesh` for `material` (linear E, nu; t for 2D; the law
/// only matters for "fem"): springs, volume and surface terms, lumped masses, the validity warnings. For "auto" the
/// model's method is the one chosen and its `choice` says why (also logged at LogLevel::kInfo).
/// A closed surface-triangle mesh given to any method but "surface" is tetrahedralized first with
/// options.tetrahedralize, and the model's `meshing` says how (its mesh is then the tets).
/// With options.regions, the listed element regions take their own E and nu (element_materials), and "auto" picks
/// for the largest nu among the materials (the hardest case of its measured table).
/// @param mesh  validated mesh, m; a closed surface-triangle mesh for "surface"
/// @throws InvalidArgument for an unknown method or one that does not apply to the mesh, a region the mesh lacks,
///   regions with "surface", InvalidMaterial,
///   InvalidMesh (the surface model's checks)
CalibratedModel calibrate_model(const mesh::Mesh& mesh, const material::Material& material,
                                const ModelOptions& options);

/// A model's term blocks, and what an interaction may drive.
struct BuiltModel {
  std::shared_ptr<model::Model> model;
  /// The surface model's volume penalty (null otherwise): its Eq. 4 weights follow a probe.
  const surface::VolumePenaltyBlock* volume_penalty = nullptr;
};

/// The term blocks of `model`: springs (and tet volume terms) with an orientation guard on the elements, the
/// FEM block for "fem", membrane springs + anchors (+ volume penalty) for a surface model.
/// @throws InvalidArgument when validate_model rejects it
BuiltModel build_model(const CalibratedModel& model);

}  // namespace hooke::calibrate
