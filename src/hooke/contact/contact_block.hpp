#pragma once
/// Unilateral contact between a body's nodes and a rigid tool or obstacle as a term block: a barrier energy in each
/// node's distance to the tool (Li et al. 2020, "Incremental Potential Contact", Eq. 6's log barrier, applied to
/// node-versus-rigid-body distances), so that every solver and integrator that minimises the model's energy keeps
/// every node outside the tool: the energy is +infinity at and beyond contact, and a line search never accepts such a
/// state. docs/contact.md.
#include <hooke/contact/rigid_tool.hpp>
#include <hooke/mesh/mesh.hpp>
#include <hooke/model/term_block.hpp>
#include <memory>
#include <vector>

namespace hooke::contact {

/// The barrier b(d) = -(d - dhat)^2 ln(d / dhat) for 0 < d < dhat, 0 from dhat on, +infinity at d <= 0
/// (dimensionless factor times m^2), with b'(d) and b''(d). Exposed for tests.
struct Barrier {
  double value, slope, curvature;
};
Barrier barrier(double distance, double activation);

class ContactBlock final : public model::TermBlock {
 public:
  /// @param nodes       the nodes that may touch the tool (the body's boundary nodes), each once
  /// @param stiffness   kappa per node, N/m (> 0): E_i = kappa_i b(d_i) (contact_stiffness gives one from E and area)
  /// @param activation  dhat, m (> 0): the distance below which the barrier pushes; a node in contact rests between
  ///                    0 and dhat from the tool's surface
  /// @param tool        the tool, shared with whoever moves it (its pose is read at every evaluation)
  /// @throws InvalidArgument for sizes that differ, a non-positive stiffness or activation, or a null tool
  ContactBlock(std::vector<int> nodes, VecX stiffness, double activation, std::shared_ptr<const RigidTool> tool);

  std::string_view name() const override { return "contact"; }
  double energy(const Eigen::Ref<const VecX>& x) const override;
  void add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const override;
  double energy_and_add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const override;
  RowMatXi element_nodes() const override;
  void add_hessian_values(const Eigen::Ref<const VecX>& x, const model::HessianScatter& scatter, double* values,
                          bool project_psd) const override;

  /// The force the body exerts on the tool at x, N: sum over the nodes of kappa_i b'(d_i) n_i (minus the contact
  /// forces on the nodes). Zero when no node is within the activation distance.
  Vec3 tool_force(const Eigen::Ref<const VecX>& x) const;
  /// The torque of those forces about the tool's position, N m (each applied at its node's closest tool point).
  Vec3 tool_torque(const Eigen::Ref<const VecX>& x) const;
  /// Moves every contact node nearer the tool than `distance` (m, in (0, activation)) out along the tool's normal to
  /// that distance: an admissible start (finite energy) after the tool has moved by more than the gap. Returns how
  /// many nodes moved.
  int push_out(Eigen::Ref<VecX> x, double distance) const;
  /// Nodes within the activation distance at x.
  int active_count(const Eigen::Ref<const VecX>& x) const;
  /// The smallest distance of a contact node to the tool at x, m (negative: a node is inside).
  double smallest_distance(const Eigen::Ref<const VecX>& x) const;

  const std::vector<int>& nodes() const { return m_nodes; }
  double activation() const { return m_activation; }
  const RigidTool& tool() const { return *m_tool; }

 private:
  /// Calls f(k, distance, barrier) for every node m_nodes[k] within the activation distance at x.
  template <class F>
  void for_each_touching(const Eigen::Ref<const VecX>& x, F&& f) const;

  std::vector<int> m_nodes;
  VecX m_stiffness;
  double m_activation;
  std::shared_ptr<const RigidTool> m_tool;
};

/// kappa per node from the body's Young's modulus and each node's share of the boundary area: kappa_i = E A_i / dhat
/// (N/m). Then the barrier's force, kappa_i |b'(d)|, passes the pressure E A_i (a pressure equal to Young's modulus,
/// far beyond any tissue's) before d reaches dhat / 2, so a node in contact stays within dhat of the tool.
/// @param boundary_area  per node of `nodes`, m^2 (> 0)
VecX contact_stiffness(double youngs_modulus, const VecX& boundary_area, double activation);

/// A contact block on the boundary of `mesh` against `tool`: the nodes of its boundary triangles (tets) or all its
/// nodes (a closed surface of triangles, the surface model's mesh), each with its share of the boundary area and
/// kappa from contact_stiffness.
/// @param activation  dhat, m; 0: 1 % of the mean boundary edge length
/// @throws InvalidArgument for a 2D mesh (contact is 3D) or a negative activation
std::unique_ptr<ContactBlock> boundary_contact(const mesh::Mesh& mesh, double youngs_modulus,
                                               std::shared_ptr<const RigidTool> tool, double activation = 0.0);

}  // namespace hooke::contact
