#pragma once
/// Zero-length inner ("anchor", shape-preserving) springs of Arnab & Raja, Eq. 2: each node is pulled back to
/// its anchor, its rest position, fixed in the world.
#include <hooke/model/term_block.hpp>
#include <vector>

namespace hooke::surface {

/// How an anchor's stiffness depends on the direction of its stretch d = p'_i - p_i.
enum class AnchorLaw {
  /// K_i = K_E,i in every direction: E = K_E/2 |d|^2 (schemes A-C, one stiffness dimension). Conservative.
  kSingle,
  /// The paper's run-time blend: K_i = |N_i . F^_i| K_E + (1 - |N_i . F^_i|) K_G, force -K_i d. F^_i, "the
  /// acting force unit vector at node i", is read as the anchor's own force direction -d^ (at rest under a
  /// load the anchor balances the other forces on the node, so both readings agree). The force is radial in d
  /// with a direction-dependent magnitude: it has no potential (not conservative). |N . F^| is read as
  /// c = sqrt(d^T P_i d^) with P_i the node's normal cone (normal_cone.hpp: N_i N_i^T, so c = |N_i . d^|, except at
  /// a crease) and smoothed at 0, (sqrt(c^2 + 0.01^2) - 0.01) / (sqrt(1 + 0.01^2) - 0.01), so that Newton's method
  /// converges where a node moves in its tangent plane; still exactly K_E for a normal and K_G for a tangential
  /// stretch.
  kBlend,
  /// Conservative alternative with the same two extremes: E = 1/2 d^T (K_E P + K_G (I - P)) d (P = N N^T off
  /// creases), the stiffness along d then blends by (N . d^)^2 instead of |N . d^|.
  kTensor,
};

/// Stable name of a law: "single", "blend" or "tensor".
std::string_view anchor_law_name(AnchorLaw law);
/// The law named `name`. @throws InvalidArgument for another name
AnchorLaw anchor_law_from_name(std::string_view name);

/// All anchors of a surface model, one per node.
class AnchorBlock final : public model::TermBlock {
 public:
  /// @param anchors   flat anchor positions, m (3 per node)
  /// @param cones     #V x 6 packed normal cones P_i at rest (normal_cone.hpp), symmetric with eigenvalues in
  ///                  [0, 1]; N_i N_i^T for a smooth node
  /// @param k_normal  K_E,i, N/m, >= 0
  /// @param k_shear   K_G,i, N/m, >= 0 (unused by kSingle)
  /// @throws InvalidArgument on mismatched sizes or negative stiffnesses
  AnchorBlock(VecX anchors, const RowMatX& cones, VecX k_normal, VecX k_shear, AnchorLaw law);

  std::string_view name() const override { return "anchors"; }
  bool conservative() const override { return m_law != AnchorLaw::kBlend; }
  /// kBlend: 1/2 K_i(d^) |d|^2, the work-like measure reported (not a potential of the force).
  double energy(const Eigen::Ref<const VecX>& x) const override;
  void add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const override;
  RowMatXi element_nodes() const override;
  /// kBlend: the symmetric part of the force Jacobian, K_i I + (K_E - K_G) sym(d^ (P d^ - q d^)^T) / s with
  /// q = d^T P d^ and s = sqrt(q + 0.01^2) (sqrt(1 + 0.01^2) - 0.01), the derivative of the smoothed weight (K_E I at
  /// d = 0, the stiffest direction, so that explicit step limits stay safe); with project_psd just K_i I.
  void add_hessian_values(const Eigen::Ref<const VecX>& x, const model::HessianScatter& scatter, double* values,
                          bool project_psd) const override;

  /// Stiffness K_i (N/m) of node i's anchor for a stretch along `direction` (any non-zero vector).
  double stiffness_along(int node, const Vec3& direction) const;
  AnchorLaw law() const { return m_law; }

 private:
  VecX m_anchors;
  std::vector<Mat3> m_cones;
  VecX m_k_normal, m_k_shear;
  AnchorLaw m_law;
};

}  // namespace hooke::surface
