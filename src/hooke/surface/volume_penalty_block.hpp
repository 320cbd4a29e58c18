#pragma once
/// The volume penalty of Arnab & Raja (Eq. 3, with the weighted constraints of Eq. 4): forces along the node
/// normals, proportional to the bulk stiffness and the volume lost, that push a surface model back to its
/// rest volume.
#include <hooke/model/term_block.hpp>
#include <vector>

namespace hooke::surface {

/// The readings of Eq. 3, F_i = K_B,i dV w_i N_i, with dV = V_0 - V (so that a compressed body pushes out).
///
/// kNodal, the consistent reading (default): dV is taken as the volumetric strain (V_0 - V)/V_0 and made a
/// force by the node's axis length, F_i = K_B,i L'_i (V_0 - V)/V_0 w_i N_i (N). Since K_B,i L'_i =
/// K sum_t V_t / L'_i and V_t = A_t L'_i / 3 on a flat neighbourhood, this is the bulk pressure K (V_0 - V)/V_0
/// on the node's share of the area (K = E / (3 (1 - 2 nu)), the bulk modulus).
/// kPrinted: F_i = K_B,i (V_0 - V) w_i N_i with the volume in m^3, as printed (units N m^2: the force then
/// depends on the unit of length; kept for reproducing the paper).
/// kEnergy, a conservative alternative: the energy K/(2 V_0) (V - V_0)^2, whose force is the uniform pressure
/// K (V_0 - V)/V_0 times dV/dx_i (w_i = 1, no per-node stiffness).
enum class VolumeForce { kNodal, kPrinted, kEnergy };

/// Stable names "nodal", "printed", "energy"; volume_force_from_name throws InvalidArgument on others.
std::string_view volume_force_name(VolumeForce force);
VolumeForce volume_force_from_name(std::string_view name);

/// Where an interaction (a probe, a haptic device) pushes: the weights of Eq. 4 follow it. It lives in the problem
/// (model::Problem::interaction), not in the block.
using Interaction = model::Interaction;

/// Weights of Eq. 4 at positions x: w_i = ((p_i - p_f)/|p_i - p_f| . F^_f) cos(pi |p_i - p_f| / (2 r)) for
/// nodes within r of p_f, 0 elsewhere. The printed "(p_i - p_f . F_f)/|p_i - p_f|" is read as the cosine of
/// the angle between p_i - p_f and F_f (the printed brackets make no sense); negative weights (nodes behind the
/// push) are set to 0; then all are scaled so that they sum to the node count (Hong et al. 2006). When no node
/// gets a positive weight, all weights are 1.
VecX interaction_weights(const Eigen::Ref<const VecX>& x, const Interaction& interaction);

class VolumePenaltyBlock final : public model::TermBlock {
 public:
  /// @param triangles      #T x 3 outward-oriented triangles of the closed surface
  /// @param rest_volume    V_0, m^3 (> 0)
  /// @param k_bulk         K_B,i per node, N/m (>= 0; unused by kEnergy)
  /// @param normal_length  L'_i per node, m (> 0; used by kNodal)
  /// @param bulk_modulus   K, Pa (> 0; used by kEnergy and the reported energy)
  VolumePenaltyBlock(RowMatXi triangles, double rest_volume, VecX k_bulk, VecX normal_length, double bulk_modulus,
                     VolumeForce force);

  std::string_view name() const override { return "volume"; }
  bool conservative() const override { return m_force == VolumeForce::kEnergy; }
  bool exact_hessian() const override { return false; }
  /// K/(2 V_0) (V - V_0)^2, J (a potential only for kEnergy).
  double energy(const Eigen::Ref<const VecX>& x) const override;
  void add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const override;
  RowMatXi element_nodes() const override;
  /// Sparse approximation: the rank-one term (K/V_0) g g^T (g = dV/dx) couples every node with every other;
  /// only its node-diagonal blocks are kept (the matrix would be dense), plus, for kEnergy without
  /// project_psd, the pressure term K (V - V_0)/V_0 d2V/dx2 per triangle. A modified Newton matrix.
  void add_hessian_values(const Eigen::Ref<const VecX>& x, const model::HessianScatter& scatter, double* values,
                          bool project_psd) const override;

  /// Under an interaction the weights of Eq. 4 and the force directions (p_i - p_f)/|p_i - p_f| follow it (nodal
  /// and printed readings; kEnergy ignores it); without one (add_gradient), w_i = 1 along the node normals N_i.
  bool follows_interaction() const override { return m_force != VolumeForce::kEnergy; }
  void add_interaction_gradient(const Eigen::Ref<const VecX>& x, const Interaction& interaction,
                                Eigen::Ref<VecX> gradient) const override;
  void add_interaction_hessian_values(const Eigen::Ref<const VecX>& x, const Interaction& interaction,
                                      const model::HessianScatter& scatter, double* values,
                                      bool project_psd) const override;
  /// The weights at x under `interaction` (all 1 without one).
  VecX weights(const Eigen::Ref<const VecX>& x, const Interaction* interaction = nullptr) const;
  VolumeForce force() const { return m_force; }

 private:
  void add_forces(const Eigen::Ref<const VecX>& x, const Interaction* interaction, Eigen::Ref<VecX> gradient) const;
  void add_stiffness(const Eigen::Ref<const VecX>& x, const Interaction* interaction,
                     const model::HessianScatter& scatter, double* values, bool project_psd) const;

  RowMatXi m_triangles;
  double m_rest_volume, m_bulk_modulus;
  VecX m_k_bulk, m_normal_length;
  VolumeForce m_force;
};

}  // namespace hooke::surface
