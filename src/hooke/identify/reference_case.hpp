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
};

/// The cases that are fitted (not held out), in their order: pointers into `cases`.
std::vector<const ReferenceCase*> training_cases(const std::vector<ReferenceCase>& cases);

/// Checks sizes (positions, forces and fixed flags of dof_count entries each) and finiteness.
/// @throws InvalidArgument naming the case and what is wrong
void validate_reference(const ReferenceCase& reference, Eigen::Index dof_count);

}  // namespace hooke::identify
