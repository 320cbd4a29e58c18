#include <hooke/core/error.hpp>
#include <hooke/identify/reference_case.hpp>

namespace hooke::identify {

std::vector<const ReferenceCase*> training_cases(const std::vector<ReferenceCase>& cases) {
  std::vector<const ReferenceCase*> out;
  for (const ReferenceCase& c : cases)
    if (!c.held_out) out.push_back(&c);
  return out;
}

void validate_reference(const ReferenceCase& reference, Eigen::Index dof_count) {
  const std::string what = "reference case '" + reference.name + "'";
  if (reference.positions.size() != dof_count || reference.external_force.size() != dof_count ||
      static_cast<Eigen::Index>(reference.fixed_dofs.size()) != dof_count)
    throw InvalidArgument(what + ": positions, forces and fixed flags need " + std::to_string(dof_count) +
                          " entries each (one per DOF)");
  for (Eigen::Index k = 0; k < dof_count; ++k) {
    if (!std::isfinite(reference.positions(k)))
      throw InvalidArgument(what + ": the position of DOF " + std::to_string(k) + " is not finite");
    if (!reference.fixed_dofs[k] && !std::isfinite(reference.external_force(k)))
      throw InvalidArgument(what + ": the force on DOF " + std::to_string(k) + " is not finite");
  }
}

}  // namespace hooke::identify
