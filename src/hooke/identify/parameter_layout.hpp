#pragma once
/// What identification fits (the vector theta of Lloyd et al. 2007, Eq. 1-2) and how theta becomes a spring model.
#include <array>
#include <hooke/calibrate/spring_model.hpp>
#include <hooke/mesh/mesh.hpp>
#include <string_view>
#include <vector>

namespace hooke::identify {

/// Stable names: "springs", "springs+volume", "springs+volume+rest-length".
enum class Parameters {
  kSprings,                  ///< k >= 0 per mesh edge; rest lengths are the rest edge lengths
  kSpringsVolume,            ///< and k_V >= 0 per tet (the volume term of Eq. 14, E = k_V/(2 V0^2) (V - V0)^2)
  kSpringsVolumeRestLength,  ///< and a free offset delta = k (L - l0) per spring: the rest length l0 is fitted too
  /// One factor c on every k and k_V of a start model (IdentifyOptions::start_model), by Eq. 1 (scale_fit.hpp):
  /// the analytic model made as compliant as the reference. Not a layout of its own (parameter_layout refuses it).
  kScale
};
Parameters parameters_from_name(std::string_view name);  ///< @throws InvalidArgument listing the names
std::string_view parameters_name(Parameters parameters);

/// The unknowns on one mesh, in the order theta = [k per spring | k_V per tet | delta per spring].
/// With theta so ordered, the force the model resists with at positions x, dE/dx, is linear in theta (Eq. 2):
/// spring s = (i, j) adds k (l - l0) u at j and its negative at i (u = (x_j - x_i)/l, l = |x_j - x_i|, l0 = the
/// layout's rest length) plus delta u at j and -delta u at i; tet t adds k_V (V - V0)/V0^2 dV/dx.
struct ParameterLayout {
  Parameters parameters = Parameters::kSprings;
  int dim = 3;
  std::vector<std::array<int, 2>> pairs;  ///< springs: the mesh edges (i < j)
  VecX rest_length;                       ///< l0 of the k columns per spring, m (the rest edge lengths unless refitted)
  RowMatXi tets;                          ///< tets with a volume term (#T x 4; empty without volume terms)
  VecX rest_volume;                       ///< V0 per tet, m^3
  /// k_V may be negative. A spring network alone has Poisson's ratio 1/4 (Cauchy's relation lambda = mu), so below
  /// nu = 1/4 the volume terms must take stiffness away (docs/methods/any_nu.md); default false (k_V >= 0)
  bool negative_volume = false;
  /// The term law every k and k_V column is of (calibrate::SpringModel::spring_exponent, volume_exponent;
  /// docs/methods/large_strain.md): spring s adds k l0 g_m'(l / l0) u, tet t adds k_V g_q'(V / V0) / V0 dV/dx, linear
  /// in theta for every law. Default 1 (the Hookean columns above); offsets need m = 1, a law q != 1 needs k_V >= 0.
  double spring_exponent = 1.0;
  double volume_exponent = 1.0;

  int spring_count() const { return static_cast<int>(pairs.size()); }
  int volume_count() const { return static_cast<int>(tets.rows()); }
  /// Offsets delta (= spring_count() with kSpringsVolumeRestLength, else 0).
  int offset_count() const { return parameters == Parameters::kSpringsVolumeRestLength ? spring_count() : 0; }
  int size() const { return spring_count() + volume_count() + offset_count(); }
  /// 0 for k and k_V (no negative springs), -infinity for the offsets and, with negative_volume, for k_V.
  VecX lower_bounds() const;
};

/// The layout of `parameters` on a triangle or tet mesh: one spring per edge; volume terms on tets only.
/// @throws InvalidArgument for volume parameters on a 2D mesh, or another element kind
ParameterLayout parameter_layout(const mesh::Mesh& mesh, Parameters parameters);

/// The spring model of theta. With offsets, each spring's rest length is l0 = L - delta/k, kept in [L/2, 2L]
/// (l0 = L where k = 0); `clamped` (if not null) receives how many springs were outside that range. Negative k are
/// taken as 0, and negative k_V too unless layout.negative_volume.
/// @pre theta.size() == layout.size()
calibrate::SpringModel spring_model(const ParameterLayout& layout, const VecX& theta, int* clamped = nullptr);

/// theta of a spring model on the same springs (k, and k_V where the layout has volume terms; offsets 0).
/// Springs of the layout missing from `springs` get k = 0. @throws InvalidArgument when volume terms differ in count
VecX parameters_of(const ParameterLayout& layout, const calibrate::SpringModel& springs);

}  // namespace hooke::identify
