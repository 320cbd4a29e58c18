#pragma once
/// The matrix U(x) of Lloyd et al. 2007, Eq. 2: the force each parameter of a ParameterLayout resists with at
/// positions x, per unit of that parameter, so that dE/dx (x; theta) = U(x) theta. Kept as one small column block
/// per spring and per tet, never as a sparse matrix.
#include <hooke/identify/parameter_layout.hpp>
#include <hooke/identify/reference_case.hpp>

namespace hooke::identify {

class ForceBasis {
 public:
  /// @param layout     the unknowns (kept by reference: it must outlive the basis)
  /// @param positions  flat node positions, m (dim x #V); springs of zero length contribute nothing
  ForceBasis(const ParameterLayout& layout, const Eigen::Ref<const VecX>& positions);
  /// forces = U theta, N (flat, dim x #V).
  void apply(const Eigen::Ref<const VecX>& theta, Eigen::Ref<VecX> forces) const;
  /// theta_out = U^T r (layout.size()), with r flat over the nodes.
  /// @pre r is zero on the rows that must not count (the supports' DOFs)
  void apply_transpose(const Eigen::Ref<const VecX>& r, Eigen::Ref<VecX> theta_out) const;
  /// Adds |column|^2 over the rows where `row_mask` is 1 to `out` (layout.size()).
  void add_squared_column_norms(const std::vector<char>& row_mask, Eigen::Ref<VecX> out) const;

  /// The column blocks: per spring (l - l0) u and u (the latter only with offsets), #S x dim; per tet the four
  /// corners' (V - V0)/V0^2 dV/dx_a, #T x 12 (empty without volume terms); for a layout's term law the columns of
  /// that law (ParameterLayout::spring_exponent, volume_exponent).
  const RowMatX& stretch() const { return m_stretch; }
  const RowMatX& direction() const { return m_direction; }
  const RowMatX& volume() const { return m_volume; }

 private:
  const ParameterLayout& m_layout;
  int m_dim;
  RowMatX m_stretch;    ///< per spring: (l - l0) u (#S x dim), the k column at node j (minus at node i)
  RowMatX m_direction;  ///< per spring: u (#S x dim), the delta column (offsets only)
  RowMatX m_volume;     ///< per tet: (V - V0)/V0^2 dV/dx_a for the four corners (#T x 12)
};

}  // namespace hooke::identify
