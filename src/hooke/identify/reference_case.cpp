#include <hooke/core/error.hpp>
#include <hooke/identify/reference_case.hpp>

namespace hooke::identify {

std::vector<const ReferenceCase*> training_cases(const std::vector<ReferenceCase>& cases) {
  std::vector<const ReferenceCase*> out;
  for (const ReferenceCase& c : cases)
    if (!c.held_out) out.push_back(&c);
  return out;
}

std::vector<char> held_dofs(const ReferenceCase& reference) {
  std::vector<char> held = reference.fixed_dofs;
  for (std::size_t k = 0; k < reference.prescribed_dofs.size() && k < held.size(); ++k)
    if (reference.prescribed_dofs[k]) held[k] = 1;
  return held;
}

bool has_prescribed(const ReferenceCase& reference) {
  for (char p : reference.prescribed_dofs)
    if (p) return true;
  return false;
}

VecX prescribed_part(const ReferenceCase& reference, const VecX& values) {
  VecX out = VecX::Zero(values.size());
  for (std::size_t k = 0; k < reference.prescribed_dofs.size(); ++k)
    if (reference.prescribed_dofs[k]) out(static_cast<Eigen::Index>(k)) = values(static_cast<Eigen::Index>(k));
  return out;
}

void validate_reference(const ReferenceCase& reference, Eigen::Index dof_count) {
  const std::string what = "reference case '" + reference.name + "'";
  if (reference.positions.size() != dof_count || reference.external_force.size() != dof_count ||
      static_cast<Eigen::Index>(reference.fixed_dofs.size()) != dof_count)
    throw InvalidArgument(what + ": positions, forces and fixed flags need " + std::to_string(dof_count) +
                          " entries each (one per DOF)");
  if (!reference.prescribed_dofs.empty() && static_cast<Eigen::Index>(reference.prescribed_dofs.size()) != dof_count)
    throw InvalidArgument(what + ": the prescribed flags need " + std::to_string(dof_count) + " entries (one per DOF)");
  for (Eigen::Index k = 0; k < dof_count; ++k) {
    if (!std::isfinite(reference.positions(k)))
      throw InvalidArgument(what + ": the position of DOF " + std::to_string(k) + " is not finite");
    if (!reference.fixed_dofs[k] && !std::isfinite(reference.external_force(k)))
      throw InvalidArgument(what + ": the force on DOF " + std::to_string(k) + " is not finite");
    if (!reference.prescribed_dofs.empty() && reference.prescribed_dofs[k] && reference.fixed_dofs[k])
      throw InvalidArgument(what + ": DOF " + std::to_string(k) + " is both a support and prescribed");
  }
}

}  // namespace hooke::identify
