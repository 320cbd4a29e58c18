#pragma once
/// A calibrated model as plain data: what `hooke calibrate` writes and `--model` reads back (docs/model_format.md).
/// It holds everything the term blocks are built from, so that a model made here, in another program or by hand
/// runs in every solver and comparison (docs/architecture.md: the model is data).
#include <functional>
#include <hooke/calibrate/region_materials.hpp>
#include <hooke/calibrate/spring_model.hpp>
#include <hooke/material/material.hpp>
#include <hooke/mesh/mesh.hpp>
#include <hooke/surface/anchor_block.hpp>
#include <hooke/surface/volume_penalty_block.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hooke::calibrate {

/// What a model is made of: it decides how the model is built, compared and remade, never its method's spelling.
enum class ModelKind {
  kSprings,  ///< "springs": springs (with volume or area terms) of a calibration method, remade from E and nu
  kSurface,  ///< "surface": Arnab & Raja's surface model
  kFem,      ///< "fem": the finite elements of the material's law
  kFile      ///< "file": constants hooke cannot remake (identified, hand-tuned, made by another program)
};
/// Stable names of the kinds ("springs", "surface", "fem", "file").
std::string_view model_kind_name(ModelKind kind);
/// The kind a model factory name stands for: a calibration method or "auto" kSprings, "surface", "fem", and "file"
/// (the model's own constants). @throws InvalidArgument for any other name, listing them
ModelKind model_kind_of_method(std::string_view method);

/// The inner terms of Arnab & Raja's surface model, per node of the (outward-oriented) surface mesh.
struct SurfaceTerms {
  std::string scheme = "D";    ///< distribution scheme "A".."D" (for reports)
  Vec3 centre = Vec3::Zero();  ///< object centre c of the radial discretisation, m
  surface::AnchorLaw anchor_law = surface::AnchorLaw::kBlend;
  RowMatX normals;             ///< #V x 3 unit node normals N_i at rest
  RowMatX normal_cones;        ///< #V x 6 packed normal cones P_i (surface/normal_cone.hpp): N_i N_i^T off creases
  VecX k_normal;               ///< K_E,i per node, N/m (>= 0)
  VecX k_shear;                ///< K_G,i per node, N/m (>= 0)
  bool volume_penalty = true;  ///< Eq. 3 present
  surface::VolumeForce volume_force = surface::VolumeForce::kNodal;
  double rest_volume = 0.0;   ///< V_0 enclosed at rest, m^3 (> 0 with the penalty)
  double bulk_modulus = 0.0;  ///< K = E / (3 (1 - 2 nu)), Pa
  VecX k_bulk;                ///< K_B,i per node, N/m (>= 0)
  VecX normal_length;         ///< L'_i per node, m (> 0)
};

/// The measured error of a model against the FEM on one load case (`hooke calibrate --certify`).
struct CertificateCase {
  std::string load;                  ///< "stretch", "compress" or "shear"
  double strain = 0.0;               ///< mean top strain: of the linear FEM (traction), or the top's move / height
  double max_error = 0.0;            ///< max node distance |x_model - x_fem|, m
  double mean_error = 0.0;           ///< mean node distance, m
  double relative_l2 = 0.0;          ///< ||u_model - u_fem|| / ||u_fem|| over all nodes
  std::string control = "traction";  ///< "traction" or "displacement" (model::LoadControl)
  std::string reference = "linear";  ///< the FEM's law: "linear", "stvk" or "neohookean"
  double force_error = 0.0;          ///< |R_model - R_fem| / |R_fem| of the force on the top (displacement control)
};

/// A model ready to be built into term blocks (build_model) or written to a file (write_model).
struct CalibratedModel {
  std::string method;           ///< stable name: a calibration method, "surface", "fem", or what a file says
  std::string equation;         ///< where its constants come from ("Lloyd et al. 2007, Eq. 12-13")
  std::string choice;           ///< why `method` was chosen, for "auto" (calibrate::choose_method); else empty
  std::string meshing;          ///< how `mesh` was made from a closed surface (TetrahedralizeReport::summary)
  mesh::Mesh mesh;              ///< rest nodes (m) and the elements the model stands for
  material::Material material;  ///< E (Pa), nu, thickness (m, 2D); the law is used by "fem" only
  /// E and nu of the listed element regions (mesh.region); the other elements have `material`'s. Empty: one
  /// material for the whole body (calibrate::element_materials; docs/regions.md).
  std::vector<RegionMaterial> regions;
  double density = 1000.0;                   ///< kg/m^3, what the masses were made from
  VecX masses;                               ///< lumped mass per DOF, kg (dim x #V, > 0)
  SpringModel springs;                       ///< springs and tet volume terms (empty for "fem")
  std::optional<SurfaceTerms> surface;       ///< anchors and volume penalty of the surface model
  std::vector<std::string> warnings;         ///< the method's validity warnings (calibrate::validity_warnings)
  std::vector<CertificateCase> certificate;  ///< measured error against FEM, when certified
};

/// The kind of `model`: kSurface with surface terms, else its method's kind (model_kind_of_method), kFile for a
/// method hooke does not know (an identified or hand-tuned model's).
ModelKind model_kind(const CalibratedModel& model);

/// The material of each of `model`'s elements ({model.material} when it has no regions): what its FEM reference
/// and a recalibration take. @throws InvalidArgument as element_materials
std::vector<material::Material> element_materials(const CalibratedModel& model);

/// Checks that `model` is consistent: node and element indices in range, finite positions, k >= 0, l0 > 0,
/// volume terms on tets with V0 > 0 and k_V >= 0, masses > 0,
/// surface arrays of one entry per node. Throws naming the entry as the model file does ("springs[12]").
/// @param source  name used in messages (the file)
/// @throws InvalidArgument naming `source` and the entry
void validate_model(const CalibratedModel& model, const std::string& source);

/// Receives validate_model's rejection: the entry ("springs[12]") and why; it must throw.
using ModelRejection = std::function<void(const std::string& entry, const std::string& why)>;
/// validate_model's checks with the rejection handed to `reject` (a model file's reader raises ParseError with it).
void validate_model(const CalibratedModel& model, const ModelRejection& reject);

/// Checks that `model` stands on `mesh`: the same node count and rest positions (within 1e-9 of the bounding-box
/// diagonal), so that a model file is run on the mesh it was made for.
/// @throws InvalidArgument naming both and the first node that differs
void require_same_nodes(const CalibratedModel& model, const mesh::Mesh& mesh);

/// The same model with its nodes renumbered: new node k is old node new_to_old[k] (a permutation of #V).
/// Spring i < j order is restored; spring order is kept.
CalibratedModel permute_nodes(const CalibratedModel& model, const std::vector<int>& new_to_old);

}  // namespace hooke::calibrate
