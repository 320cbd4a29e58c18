#pragma once
/// The matrix of Lloyd et al. 2007, Eq. 2 for several reference cases at once: U(p_1), ..., U(p_C) stacked, each
/// case's rows of supported DOFs masked out. Stored per spring and per tet with the columns of a group of cases side
/// by side, so that one pass over the mesh serves the whole group (the products are bound by memory traffic).
#include <hooke/identify/bounded_least_squares.hpp>
#include <hooke/identify/parameter_layout.hpp>
#include <hooke/identify/reference_case.hpp>
#include <vector>

namespace hooke::identify {

class StackedForceOperator final : public LinearOperator {
 public:
  /// @param layout  the unknowns (kept by reference: it must outlive the operator)
  /// @param cases   the cases' positions (m) and supports; not kept
  /// @param groups  how many groups of cases the products are split into (one thread each), at least 1; the
  ///                default is one group per OpenMP thread
  StackedForceOperator(const ParameterLayout& layout, const std::vector<const ReferenceCase*>& cases, int groups = 0);

  Eigen::Index rows() const override { return m_rows; }
  Eigen::Index cols() const override { return m_layout.size(); }
  /// y = U theta, N; rows of supported DOFs are 0. Row order: row_of(case, dof).
  void apply(const VecX& x, VecX& y) const override;
  /// x = U^T y over the rows that are not masked.
  void apply_transpose(const VecX& y, VecX& x) const override;
  VecX squared_column_norms() const override;

  /// The row of DOF `dof` (flat node-major, dim x #V) of case `c` (in the order given).
  Eigen::Index row_of(int c, Eigen::Index dof) const;
  /// The applied forces (N) of the cases on their unsupported DOFs, in row order: Eq. 2's right-hand side.
  VecX right_hand_side(const std::vector<const ReferenceCase*>& cases) const;

 private:
  struct Group {
    int first = 0, count = 0;  // cases [first, first + count)
    Eigen::Index row0 = 0;     // rows of the group: [node][case in group][dof of node]
    RowMatX stretch;           // #S x (count dim)
    RowMatX direction;         // #S x (count dim), offsets only
    RowMatX volume;            // #T x (count 12)
    std::vector<char> free;    // per row of the group: 1 unless the DOF is supported in that case
  };
  void apply_group(const Group& g, const VecX& theta, double* y) const;
  void transpose_group(const Group& g, const double* y, VecX& theta) const;

  const ParameterLayout& m_layout;
  int m_nodes = 0;
  Eigen::Index m_rows = 0;
  std::vector<Group> m_groups;
};

}  // namespace hooke::identify
