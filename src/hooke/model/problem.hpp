#pragma once
/// A static problem: a model, the nodes held fixed, and dead external forces.
#include <hooke/core/types.hpp>
#include <hooke/model/model.hpp>
#include <memory>
#include <optional>
#include <vector>

namespace hooke::model {

struct Problem {
  std::shared_ptr<const Model> model;  ///< the body
  std::vector<char> fixed_dofs;        ///< per DOF: 1 where the position is prescribed (size model->dof_count())
  VecX prescribed_positions;           ///< positions of fixed DOFs, m (entries of free DOFs ignored); rest if empty
  VecX external_force;                 ///< dead nodal forces, N (size dof_count; zero where fixed)
  /// where a probe pushes, for blocks whose forces follow it (the surface model's Eq. 4 weights); none by default
  std::optional<Interaction> interaction;
  /// The interaction or null (what Model's evaluations take).
  const Interaction* interaction_or_null() const { return interaction ? &*interaction : nullptr; }
};

/// A problem with every DOF free, no forces, fixed DOFs at their rest positions.
Problem make_problem(std::shared_ptr<const Model> model);

/// Fixes all DOFs of `nodes` at their rest positions.
void fix_nodes(Problem& problem, const std::vector<int>& nodes);

/// Sets `force` (N, per DOF) to zero on every DOF `fixed_dofs` marks: a support takes whatever load acts there.
/// @pre equal sizes
void zero_fixed_forces(const std::vector<char>& fixed_dofs, VecX& force);
/// The same on a problem's own external force.
inline void zero_fixed_forces(Problem& problem) { zero_fixed_forces(problem.fixed_dofs, problem.external_force); }

/// Indices of the free DOFs of `problem` that carry stiffness: fixed DOFs and DOFs of nodes on which the
/// model's Hessian at rest has an empty diagonal (nodes in no element) are excluded.
std::vector<int> free_dofs(const Problem& problem);

/// Total potential energy Pi(x) = E(x) - f . (x - X), J, at load factor `load_factor` on f.
double potential_energy(const Problem& problem, const Eigen::Ref<const VecX>& x, double load_factor = 1.0);
/// The same with the load `force` (flat, N, size dof_count) in place of the problem's own.
double potential_energy(const Problem& problem, const Eigen::Ref<const VecX>& x, const VecX& force, double load_factor);

/// Starting positions: rest positions with the prescribed positions of fixed DOFs applied.
VecX initial_positions(const Problem& problem);

}  // namespace hooke::model
