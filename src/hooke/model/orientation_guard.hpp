#pragma once
/// A term with no energy that makes inverted states inadmissible for models without elements of their own
/// (spring models): energy() is +infinity when any element of the mesh has non-positive signed measure.
#include <hooke/core/element_schedule.hpp>
#include <hooke/mesh/mesh.hpp>
#include <hooke/model/term_block.hpp>

namespace hooke::model {

class OrientationGuard final : public TermBlock {
 public:
  /// @param mesh  validated triangle, quad or tet mesh whose elements must keep their orientation
  /// @throws InvalidArgument for a surface mesh (it has no orientation to keep)
  explicit OrientationGuard(const mesh::Mesh& mesh);
  std::string_view name() const override { return "orientation-guard"; }
  bool has_forces() const override { return false; }
  /// 0 J, or +infinity where an element is inverted (signed area / volume <= 0; each quad as its 4 corner triangles).
  double energy(const Eigen::Ref<const VecX>& x) const override;
  void add_gradient(const Eigen::Ref<const VecX>&, Eigen::Ref<VecX>) const override {}
  RowMatXi element_nodes() const override { return {}; }
  void add_hessian_values(const Eigen::Ref<const VecX>&, const HessianScatter&, double*, bool) const override {}

 private:
  mesh::ElementKind m_kind;
  RowMatXi m_elements;
  ElementSchedule m_schedule;
};

}  // namespace hooke::model
