#pragma once
/// Area-preserving terms of planar triangles: the 2D counterpart of TetVolumeBlock, used by any-nu-triangle to carry
/// the part of the 2D lambda a spring network cannot (docs/methods/any_nu.md).
#include <hooke/model/term_block.hpp>
#include <memory>

namespace hooke::springs {

/// Energy of one triangle: E_A = k_A / (2 A0^2) (A - A0)^2, J, with the signed area
/// A = ((p2 - p1) x (p3 - p1)) / 2 (m^2, positive counter-clockwise). Gradient: k_A (A - A0) / A0^2 dA/dx with
/// dA/dp_a = J (p_c - p_b) / 2 for the corners (a, b, c) in cyclic order and J the rotation by -90 degrees;
/// Hessian: k_A / A0^2 (dA dA^T + (A - A0) d2A), d2A constant.
class TriangleAreaBlock final : public model::TermBlock {
 public:
  /// @param triangles  #T x 3 node indices of counter-clockwise triangles (2D positions)
  /// @param stiffness  k_A per triangle, J, finite
  /// @param rest_area  A0 per triangle, m^2, > 0
  /// @param exponent   Seth-Hill exponent q of the area law, as TetVolumeBlock's (1, default: the quadratic above)
  /// @throws InvalidArgument on mismatched sizes, a non-finite k_A or exponent, or a non-positive A0
  TriangleAreaBlock(RowMatXi triangles, VecX stiffness, VecX rest_area, double exponent = 1.0);

  std::string_view name() const override { return "triangle-area"; }
  double energy(const Eigen::Ref<const VecX>& x) const override;
  void add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const override;
  double energy_and_add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const override;
  RowMatXi element_nodes() const override;
  void add_hessian_values(const Eigen::Ref<const VecX>& x, const model::HessianScatter& scatter, double* values,
                          bool project_psd) const override;

 private:
  struct Terms;  // the shared loops of springs/detail/measure_terms.hpp on triangles
  std::shared_ptr<const Terms> m_terms;
};

}  // namespace hooke::springs
