#pragma once
/// Hessian assembly into a sparsity pattern built once: no triplets, no allocation per call.
#include <hooke/model/model.hpp>
#include <vector>

namespace hooke::model {

/// The pattern of a model's Hessian (a full dim x dim block for every node pair sharing an element of any block,
/// and every diagonal block), and its values refilled in place by assemble().
class HessianAssembly {
 public:
  /// Builds the pattern of `model` (which must outlive this object).
  explicit HessianAssembly(const Model& model);
  /// Builds the pattern of the given blocks alone (they must outlive this object).
  /// @param dim        2 or 3
  /// @param dof_count  dim x #nodes
  HessianAssembly(int dim, int dof_count, std::vector<const TermBlock*> blocks);

  /// Overwrites the matrix values with d2E/dx2 at x, N/m.
  /// @param x            flat positions, m (size dof_count)
  /// @param project_psd  project each element's Hessian to positive semi-definite first
  /// @param interaction  where an interaction pushes, for blocks that follow one (null: none)
  void assemble(const Eigen::Ref<const VecX>& x, bool project_psd, const Interaction* interaction = nullptr);

  /// The assembled matrix (dof_count square, both triangles stored, compressed). Its values may be changed
  /// between calls (adding masses, constraints); its pattern must not.
  SparseMatrix& matrix() { return m_matrix; }
  const SparseMatrix& matrix() const { return m_matrix; }
  /// Index into matrix().valuePtr() of the diagonal entry of each DOF.
  const std::vector<int>& diagonal() const { return m_diagonal; }

 private:
  std::vector<const TermBlock*> m_blocks;
  std::vector<HessianScatter> m_scatter;
  SparseMatrix m_matrix;
  std::vector<int> m_diagonal;
};

/// The Hessian of one block alone, N/m (dof_count square): for tests and one-off use.
SparseMatrix block_hessian(const TermBlock& block, int dim, const Eigen::Ref<const VecX>& x, bool project_psd);

}  // namespace hooke::model
