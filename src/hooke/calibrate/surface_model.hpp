#pragma once
/// The surface mass-spring model of Arnab & Raja ("A Deformable Surface Model for Soft Volume Simulation"): a
/// soft solid from its closed surface mesh alone. Membrane springs on the edges (Lloyd et al. 2007, Eq. 9),
/// a zero-length anchor at every node (Eq. 2) and the volume penalty (Eq. 3, 4), with masses and stiffnesses
/// from the radial discretisation (Fig. 5, 6).
#include <hooke/calibrate/spring_model.hpp>
#include <hooke/material/material.hpp>
#include <hooke/mesh/closed_surface.hpp>
#include <hooke/mesh/mesh.hpp>
#include <hooke/model/model.hpp>
#include <hooke/surface/anchor_block.hpp>
#include <hooke/surface/discretisation.hpp>
#include <hooke/surface/star_shape.hpp>
#include <hooke/surface/volume_penalty_block.hpp>
#include <memory>
#include <optional>

namespace hooke::calibrate {

/// The paper's distribution schemes (Sec. Experimental Findings).
enum class SurfaceScheme {
  kA,  ///< "A": uniform mass M/n and uniform inner stiffness (the mean of the K_E,i), no volume penalty
  kB,  ///< "B": irregular mass (estimation ratio) and uniform inner stiffness, no volume penalty
  kC,  ///< "C": irregular mass and irregular inner stiffness K_E,i in every direction, no volume penalty
  kD,  ///< "D": the proposed scheme: irregular mass, K_E,i / K_G,i blended by direction, volume penalty
};
/// Stable names "A".."D" (also accepted in lower case).
std::string_view surface_scheme_name(SurfaceScheme scheme);
SurfaceScheme surface_scheme_from_name(std::string_view name);

/// The shear factor of K_G = E sum V_t / L'^2 x factor.
enum class ShearFactor {
  kShearModulus,  ///< 1 / (2 (1 + nu)): K_G made from the shear modulus G = E / (2 (1 + nu)) (default)
  kPrinted,       ///< 1 / (2 (1 - nu)), as printed in the paper (read "1/2(1-nu)" with the usual precedence)
};

struct SurfaceOptions {
  SurfaceScheme scheme = SurfaceScheme::kD;
  std::optional<Vec3> centre;  ///< object centre c, m; default the volume centroid
  double density = 1000.0;     ///< kg/m^3: the object mass M = density x enclosed volume (unless mass > 0)
  double mass = 0.0;           ///< M, kg; when > 0 it replaces density x volume
  /// Membrane thickness t of the surface springs (Lloyd Eq. 9, k_ij = sum_t E t A_t / l_ij^2), m. Negative
  /// (default): default_membrane_thickness.
  double membrane_thickness = -1.0;
  std::optional<surface::AnchorLaw> anchor_law;  ///< default: kBlend for D, kSingle for A-C
  std::optional<bool> volume_penalty;            ///< default: on for D only
  surface::VolumeForce volume_force = surface::VolumeForce::kNodal;
  ShearFactor shear_factor = ShearFactor::kShearModulus;
};

/// The membrane springs' stiffness relative to the anchors' by default: t = kMembraneRatio x (mean node area A) /
/// (mean axis length L'), so that a membrane spring, about E t, is about kMembraneRatio x an anchor's K_E = E A / L'
/// at every resolution. See docs/surface.md ("Membrane thickness") for the choice.
inline constexpr double kMembraneRatio = 0.05;

/// The default membrane thickness t = kMembraneRatio x (surface area / #V) / mean L', m, of a surface whose
/// discretisation is `d`. @pre area > 0, d.normal_length > 0
double default_membrane_thickness(double area, const surface::Discretisation& d);

/// A built surface model with what the experiments and reports need.
struct SurfaceModel {
  std::shared_ptr<model::Model> model;
  mesh::Mesh mesh;                 ///< the checked, outward-oriented surface
  mesh::SurfaceCheckReport check;  ///< what check_closed_surface fixed
  surface::Discretisation discretisation;
  bool radial = true;  ///< Fig. 5's radial links from one centre; false: the depth reading (discretise_by_depth)
  VecX masses;         ///< per DOF (3 per node), kg, summing to 3 M
  VecX k_normal, k_shear, k_bulk;                       ///< K_E,i, K_G,i, K_B,i as used, N/m
  double membrane_thickness = 0.0;                      ///< t used, m
  SpringModel membrane;                                 ///< the membrane springs (empty when t = 0)
  surface::AnchorLaw law = surface::AnchorLaw::kBlend;  ///< the anchor law used
  double bulk_modulus = 0.0;                            ///< K = E / (3 (1 - 2 nu)), Pa
  const surface::AnchorBlock* anchors = nullptr;
  const surface::VolumePenaltyBlock* volume = nullptr;  ///< null without volume penalty
};

/// Builds the surface model of `mesh` (a closed triangle surface: checked and oriented, see
/// mesh::check_closed_surface) for `material` (E, nu; linear). Radial links from options.centre (or the volume
/// centroid) where the surface is star-shaped from it (surface::require_star_shaped); a surface that is not, with
/// no centre given, gets the depth reading (surface::discretise_by_depth, `radial` false).
/// @throws InvalidMesh for a surface the construction cannot use (or not star-shaped from a given centre),
///   InvalidMaterial for E, nu out of range
SurfaceModel make_surface_model(mesh::Mesh mesh, const material::Material& material,
                                const SurfaceOptions& options = {});

}  // namespace hooke::calibrate
