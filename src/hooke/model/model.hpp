#pragma once
/// A model: rest positions plus a few term blocks (docs/architecture.md: the model is data).
#include <hooke/core/types.hpp>
#include <hooke/model/term_block.hpp>
#include <memory>
#include <vector>

namespace hooke::model {

/// Immutable once built (add() aside): every evaluation is const and thread-safe, so one model may be shared by
/// several problems, solvers and threads.
class Model {
 public:
  /// @param dim             2 or 3
  /// @param rest_positions  flat node-major rest positions, m (size dim * #V)
  Model(int dim, VecX rest_positions);

  /// Adds a block; the model owns it.
  void add(std::unique_ptr<TermBlock> block);

  int dim() const { return m_dim; }
  int node_count() const { return static_cast<int>(m_rest.size()) / m_dim; }
  int dof_count() const { return static_cast<int>(m_rest.size()); }
  /// Flat rest positions, m.
  const VecX& rest_positions() const { return m_rest; }
  const std::vector<std::unique_ptr<TermBlock>>& blocks() const { return m_blocks; }

  /// True when every block is conservative (TermBlock::conservative): the forces are -dE/dx.
  bool conservative() const;
  /// True when every block's Hessian is exact (TermBlock::exact_hessian).
  bool exact_hessian() const;
  /// Total elastic energy at x, J.
  double energy(const Eigen::Ref<const VecX>& x) const;
  /// TermBlock::end_step of every block with the positions x (m) a time step starts from.
  void end_step(const Eigen::Ref<const VecX>& x) const;
  /// TermBlock::add_node_stiffness of every block into `out` (cleared first); true when a block has such terms.
  bool node_stiffness(const Eigen::Ref<const VecX>& x, std::vector<std::pair<int, Mat3>>& out) const;
  /// dE/dx at x, N (the blocks' forces: for non-conservative blocks not a gradient). With an interaction,
  /// blocks that follow one (TermBlock::follows_interaction) evaluate under it.
  VecX gradient(const Eigen::Ref<const VecX>& x, const Interaction* interaction = nullptr) const;
  /// energy(x) (J, returned) and gradient(x, gradient, interaction) (N) in one pass per block; allocates nothing.
  double energy_and_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient,
                             const Interaction* interaction = nullptr) const;
  /// Writes dE/dx at x (N) into `gradient` (size dof_count); allocates nothing.
  void gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient,
                const Interaction* interaction = nullptr) const;
  /// d2E/dx2 at x, N/m, assembled (dof_count x dof_count, symmetric).
  SparseMatrix hessian(const Eigen::Ref<const VecX>& x, bool project_psd = false,
                       const Interaction* interaction = nullptr) const;

 private:
  int m_dim;
  VecX m_rest;
  std::vector<std::unique_ptr<TermBlock>> m_blocks;
};

}  // namespace hooke::model
