#pragma once
/// The compliance of a held body at a few of its nodes: C = E^T K_ff^-1 E, the displacement of those nodes (m) per
/// force on them (N), the body's other free DOFs relaxed (statically) and its fixed DOFs held. What a local contact
/// model of a few surface nodes needs (interactive::LocalContact; docs/contact.md, the contact force at 1 kHz): its
/// inverse is the Schur complement of K onto those nodes (Guyan's static condensation), exact for the linear body.
#include <hooke/core/sparse_cholesky.hpp>
#include <hooke/core/types.hpp>
#include <unordered_map>
#include <vector>

namespace hooke::solve {

class NodeCompliance {
 public:
  /// Factorises the stiffness `k` (N/m, dof_count square, both triangles) on its free DOFs once.
  /// @param fixed  DOFs held at their place (size dof_count)
  /// @param dim    DOFs per node (1..3)
  /// @throws InvalidArgument for sizes that do not match; SolverFailure when K_ff is not positive definite (a body
  ///   not held by `fixed`)
  NodeCompliance(const SparseMatrix& k, const std::vector<char>& fixed, int dim);

  /// C restricted to `nodes` (in that order), m/N (dim |nodes| square, symmetric positive semidefinite; zero rows and
  /// columns for fixed DOFs). Each node's dim columns of K_ff^-1 are solved once and kept (up to max_cached nodes,
  /// then the cache starts again).
  /// @throws InvalidArgument for a node out of range
  MatX block(const std::vector<int>& nodes);

  int cached_nodes() const { return static_cast<int>(m_columns.size()); }
  static constexpr int max_cached = 512;

 private:
  const MatX& columns(int node);  // dof_count x dim: K_ff^-1 at the node's DOFs

  int m_dim;
  Eigen::Index m_dofs;
  std::vector<char> m_fixed;
  SparseCholesky m_factor;
  std::unordered_map<int, MatX> m_columns;
};

}  // namespace hooke::solve
