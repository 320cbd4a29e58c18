#pragma once
/// Unilateral contact between a body's nodes and a rigid tool or obstacle as a term block: a barrier energy in each
/// node's distance to the tool (Li et al. 2020, "Incremental Potential Contact", Eq. 6's log barrier, applied to
/// node-versus-rigid-body distances), so that every solver and integrator that minimises the model's energy keeps
/// every node outside the tool: the energy is +infinity at and beyond contact, and a line search never accepts such a
/// state. Coulomb friction joins it as the lagged, smoothed friction potential of the same paper (Sec. 5): the normal
/// force and the tangent plane of each touching node are frozen at the start of a step (ContactBlock::lag), and the
/// node's slip against the tool over the step is resisted by at most mu times that normal force. docs/contact.md.
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

/// The friction smoothing f0(y) = -y^3/(3 eps^2) + y^2/eps + eps/3 for 0 <= y < eps, y from eps on (m), with
/// f1 = f0' (dimensionless, rises from 0 to 1 at eps) and f1'(y) (1/m): Li et al. 2020, Eq. 14-15, with eps the slip
/// distance per step below which friction acts as a stiff spring instead of a constant force. Exposed for tests.
struct FrictionSmoothing {
  double value, slope, curvature;
};
FrictionSmoothing friction_smoothing(double slip, double eps);

/// Coulomb friction of a contact: coefficient mu (>= 0; 0: frictionless, the default) and the slip distance eps per
/// step (m, > 0 when mu > 0), below which the friction force grows linearly with the slip (a node below the friction
/// limit creeps by less than eps per step; eps = eps_v dt with eps_v a creep velocity).
struct Friction {
  double coefficient = 0.0;
  double slip = 0.0;
};

/// The creep velocity eps_v (m/s) front ends use when the user gives none: 1e-2 of the body's bounding-box diagonal
/// (m) per second. Measured (docs/contact.md): at 1e-3 of it a sphere pressed into cylinder.msh with mu = 0.3 at
/// dt 2 ms needs more than 60 Newton iterations on the step the sphere stops; at 1e-2 every step converges.
inline double default_creep_velocity(double diagonal) { return 1e-2 * diagonal; }
class ContactBlock final : public model::TermBlock {
 public:
  /// @param nodes       the nodes that may touch the tool (the body's boundary nodes), each once
  /// @param stiffness   kappa per node, N/m (> 0): E_i = kappa_i b(d_i) (contact_stiffness gives one from E and area)
  /// @param activation  dhat, m (> 0): the distance below which the barrier pushes; a node in contact rests between
  ///                    0 and dhat from the tool's surface
  /// @param tool        the tool, shared with whoever moves it (its pose is read at every evaluation)
  /// @throws InvalidArgument for sizes that differ, a non-positive stiffness or activation, or a null tool
  ContactBlock(std::vector<int> nodes, VecX stiffness, double activation, std::shared_ptr<const RigidTool> tool);

  /// Sets the friction (coefficient >= 0; a slip distance > 0 when it is > 0), shared by copies of this block.
  /// @throws InvalidArgument naming the value out of range
  void set_friction(const Friction& friction);
  Friction friction() const { return m_friction->friction; }
  /// Freezes the friction's normal forces, tangent planes, the nodes' positions x (m) and the tool's surface points
  /// they touch, for the next step: call it with the state the step starts from and the tool at the pose that state
  /// was computed with (before moving it). Shared by copies of this block; not thread-safe with evaluations (call it
  /// between steps, as RigidTool::set_pose). Without friction it does nothing.
  void lag(const Eigen::Ref<const VecX>& x) const;
  /// Nodes whose friction is active since the last lag().
  int sticking_count() const { return static_cast<int>(m_friction->lagged.size()); }
  /// lag(x): a solve::Simulator lags the friction with the state each step starts from.
  void end_step(const Eigen::Ref<const VecX>& x) const override { lag(x); }
  /// The barrier's and the friction's Hessian per touching node, projected (what add_hessian_values adds).
  bool add_node_stiffness(const Eigen::Ref<const VecX>& x, std::vector<std::pair<int, Mat3>>& out) const override;
  /// The same blocks, projected or exact (project_psd false: a curved tool's negative tangential curvature kept, what
  /// a Newton iteration converges quadratically with where the rest of the Hessian outweighs it).
  void node_hessians(const Eigen::Ref<const VecX>& x, bool project_psd, std::vector<std::pair<int, Mat3>>& out) const;
  std::string_view name() const override { return "contact"; }
  double energy(const Eigen::Ref<const VecX>& x) const override;
  void add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const override;
  double energy_and_add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const override;
  RowMatXi element_nodes() const override;
  void add_hessian_values(const Eigen::Ref<const VecX>& x, const model::HessianScatter& scatter, double* values,
                          bool project_psd) const override;

  /// The force the body exerts on the tool at x, N: sum over the nodes of kappa_i b'(d_i) n_i and their friction
  /// forces (minus the contact forces on the nodes). Zero when no node is within the activation distance.
  Vec3 tool_force(const Eigen::Ref<const VecX>& x) const;
  /// The torque of those forces about the tool's position, N m (each applied at its node's closest tool point).
  Vec3 tool_torque(const Eigen::Ref<const VecX>& x) const;
  /// Moves every contact node nearer the tool than `distance` (m, in (0, activation)) out along the tool's normal to
  /// that distance: an admissible start (finite energy) after the tool has moved by more than the gap. A lagged
  /// node's friction then counts its slip from where it was put. Returns how many nodes moved.
  int push_out(Eigen::Ref<VecX> x, double distance) const;
  /// Nodes within the activation distance at x.
  int active_count(const Eigen::Ref<const VecX>& x) const;
  /// The smallest distance of a contact node to the tool at x, m (negative: a node is inside).
  double smallest_distance(const Eigen::Ref<const VecX>& x) const;

  const std::vector<int>& nodes() const { return m_nodes; }
  const VecX& stiffness() const { return m_stiffness; }  ///< kappa per node, N/m
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

  /// What lag() froze for one node: its index in m_nodes, mu times its normal force (N), the tangent basis (3 x 2),
  /// its position, the tool's surface point it touched (world) and that point in the tool's own frame, m.
  struct Lagged {
    int k;
    double limit;
    Eigen::Matrix<double, 3, 2> tangent;
    Vec3 position, touched, tool_point;
  };
  struct FrictionState {
    Friction friction;
    std::vector<Lagged> lagged;
  };
  /// Calls f(k, 3 x 3 Hessian block) for every node m_nodes[k] with a barrier or friction Hessian at x.
  template <class F>
  void for_each_node_hessian(const Eigen::Ref<const VecX>& x, bool project_psd, F&& f) const;
  /// Calls f(point on the tool (m), force on the tool there (N)) for every contact and friction force at x.
  template <class F>
  void for_each_force_on_tool(const Eigen::Ref<const VecX>& x, F&& f) const;
  /// Calls f(lagged, slip (m, in its tangent basis), smoothing at |slip|) for every lagged node at x.
  template <class F>
  void for_each_slipping(const Eigen::Ref<const VecX>& x, F&& f) const;

  std::shared_ptr<FrictionState> m_friction = std::make_shared<FrictionState>();
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
