#pragma once
/// The local model of a pressing tool's contact for a haptic loop (docs/contact.md, the contact force at 1 kHz): the
/// surface nodes near the tool after a deformation step, their compliance C (solve::NodeCompliance: the rest of the
/// body relaxed statically) and the same barrier the body's contact block has. For a tool pose between two
/// deformation steps, the nodes' displacement d minimises
///     Phi(d) = 1/2 d^T C^-1 d + f0^T d + sum_i kappa_i b(dist_i(x0_i + d_i))
/// with f0 the barrier's force on the nodes at the step, which the body's elastic force balanced there (so d = 0 at
/// the step's pose: the model starts from the step's state), by Newton's method whose systems are solved through C by
/// Woodbury's identity on the touching nodes' 3 x 3 Hessian blocks (no factorisation per tick). The force on the tool
/// is the barrier's at the minimiser. The contact set changes between two steps as the tool moves: nodes may touch that
/// did not, and lose contact. Friction is held at the step's value (the lagged friction does not move within a
/// deformation step).
#include <Eigen/Cholesky>
#include <hooke/contact/rigid_tool.hpp>
#include <hooke/core/types.hpp>
#include <mutex>
#include <vector>

namespace hooke::interactive {

class LocalContact {
 public:
  /// @param tool        the tool at the step's pose
  /// @param positions   the nodes' positions after the step, flat (3 per node), m
  /// @param stiffness   kappa per node, N/m (> 0; contact::ContactBlock::stiffness)
  /// @param activation  the barrier's dhat, m (> 0)
  /// @param compliance  C, m/N (3 per node square, symmetric positive definite)
  /// @param step_force  the force the body exerted on the tool after the step, N (barrier and friction)
  /// @throws InvalidArgument for sizes that do not match; SolverFailure when C is not positive definite
  LocalContact(contact::RigidTool tool, VecX positions, VecX stiffness, double activation, const MatX& compliance,
               const Vec3& step_force);

  /// The force the body exerts on the tool at `pose`, N: the barrier's force at the local equilibrium, plus the
  /// step's friction force. Nodes the pose puts inside the tool start from outside it (half the activation distance).
  /// `nodes_in_contact`, when given, receives the nodes within the activation distance there. Each call starts
  /// from the last call's solution (a haptic loop's poses are near each other); thread-safe.
  Vec3 force(const contact::Pose& pose, int* nodes_in_contact = nullptr) const;

  const contact::RigidTool& tool() const { return m_tool; }  ///< at the step's pose
  int node_count() const { return static_cast<int>(m_stiffness.size()); }
  const VecX& positions() const { return m_x0; }  ///< after the step, flat, m

 private:
  contact::RigidTool m_tool;
  VecX m_x0, m_stiffness;
  double m_activation;
  MatX m_compliance;           // C
  Eigen::LLT<MatX> m_factor;   // of C: C^-1 d by two triangular solves
  VecX m_f0;                   // the barrier's force on the nodes at the step, N
  Vec3 m_held = Vec3::Zero();  // the step's friction force on the tool, N
  mutable std::mutex m_mutex;  // guards m_last
  mutable VecX m_last;         // the last call's node positions (empty: none yet), m
};

}  // namespace hooke::interactive
