#pragma once
/// Reference data for identification: one deformed state of the body with the forces that hold it there, from
/// hooke's FEM or from measurements (Lloyd et al. 2007, Sec. 2: p_ref and f_ref).
#include <hooke/core/types.hpp>
#include <string>
#include <vector>

namespace hooke::identify {

struct ReferenceCase {
  std::string name;              ///< for reports ("stretch +x", "random 2", a file name)
  VecX positions;                ///< deformed node positions p_ref, flat (dim x #V), m
  VecX external_force;           ///< applied nodal forces f_ref, flat, N (entries of fixed DOFs ignored)
  std::vector<char> fixed_dofs;  ///< per DOF: 1 where the position is prescribed (a support); its force is unknown
  bool held_out = false;         ///< true: not fitted, only used to measure the identified model
  /// Displacement control (docs/methods/identification.md): per DOF (or empty: none) 1 where an instrument holds the
  /// node at `positions` and the force it applies there is measured (`external_force`, N: the reaction dE/dx). Held in
  /// the equilibria like a support, but its force is data: a row of Eq. 2 and a term of Eq. 1.
  std::vector<char> prescribed_dofs;
};

/// Per DOF, 1 where a case holds the position (its supports and its prescribed DOFs).
std::vector<char> held_dofs(const ReferenceCase& reference);

/// Whether the case prescribes any DOF (displacement control).
bool has_prescribed(const ReferenceCase& reference);

/// `values` (flat, per DOF) on the case's prescribed DOFs and zero elsewhere (the same size as `values`).
VecX prescribed_part(const ReferenceCase& reference, const VecX& values);

/// The cases that are fitted (not held out), in their order: pointers into `cases`.
std::vector<const ReferenceCase*> training_cases(const std::vector<ReferenceCase>& cases);

/// Checks sizes (positions, forces and fixed flags of dof_count entries each; prescribed flags none or dof_count),
/// finiteness, and that no DOF is both a support and prescribed.
/// @throws InvalidArgument naming the case and what is wrong
void validate_reference(const ReferenceCase& reference, Eigen::Index dof_count);

}  // namespace hooke::identify
