#pragma once
/// Volume-preserving terms of tetrahedra (Lloyd et al. 2007, App. C.2, after Teschner et al. 2004).
#include <hooke/model/term_block.hpp>
#include <memory>

namespace hooke::springs {

/// Energy of one tet: E_V = k_V / (2 V0^2) (V - V0)^2, J, with V = (p2 - p1) . ((p3 - p1) x (p4 - p1)) / 6.
/// k_V in J (N m), volumes in m^3. Gradient: k_V (V - V0)/V0^2 dV/dx (App. C, Eq. 17 with C = (V - V0)/V0);
/// Hessian: k_V/V0^2 (dV dV^T + (V - V0) d2V), the second term vanishing at rest (Eq. 18).
/// Gradient of a tet's volume, dV/dp_a in column a (m^2), corners p in columns (m), any orientation.
/// From V = e1 . (e2 x e3) / 6 with e_k = p_{k+1} - p1 (App. C.2 with its sign erratum corrected, see
/// docs/methods/springs.md).
Eigen::Matrix<double, 3, 4> tet_volume_gradient(const Eigen::Matrix<double, 3, 4>& corners);

class TetVolumeBlock final : public model::TermBlock {
 public:
  /// @param tets        #T x 4 node indices of positively oriented tets
  /// @param stiffness   k_V per tet, J, finite; negative where a model takes volumetric stiffness away from its
  ///                    springs (any-nu-tet below nu = 1/4: the energy is then concave in V, bounded only by the
  ///                    springs, docs/methods/any_nu.md)
  /// @param rest_volume V0 per tet, m^3, > 0
  /// @param exponent    Seth-Hill exponent q of the volume law (docs/methods/large_strain.md), finite: the energy is
  ///                    k_V g_q(V / V0) with g_q = ((r^q - 1)/q)^2 / 2 (g_0 = (ln r)^2 / 2), the same at small strain
  ///                    for every q; 1 (default) is the quadratic above, q <= 0 grows without bound as V -> 0 (a
  ///                    tet cannot be flattened or inverted). Tets with k_V < 0 keep q = 1.
  /// @throws InvalidArgument on mismatched sizes, a non-finite k_V or exponent, or a non-positive V0
  TetVolumeBlock(RowMatXi tets, VecX stiffness, VecX rest_volume, double exponent = 1.0);
  double exponent() const;

  std::string_view name() const override { return "tet-volume"; }
  double energy(const Eigen::Ref<const VecX>& x) const override;
  void add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const override;
  double energy_and_add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const override;
  RowMatXi element_nodes() const override;
  void add_hessian_values(const Eigen::Ref<const VecX>& x, const model::HessianScatter& scatter, double* values,
                          bool project_psd) const override;

 private:
  struct Terms;  // the shared loops of springs/detail/measure_terms.hpp on tets (immutable, so shared by copies)
  std::shared_ptr<const Terms> m_terms;
};

}  // namespace hooke::springs
