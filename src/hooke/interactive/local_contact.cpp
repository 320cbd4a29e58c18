#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <hooke/contact/contact_block.hpp>
#include <hooke/core/error.hpp>
#include <hooke/interactive/local_contact.hpp>
#include <memory>
#include <numeric>
#include <string>

namespace hooke::interactive {
namespace {

// A contact block on the local nodes 0..k-1 against `tool` (the local model's x holds only those nodes).
contact::ContactBlock local_block(const VecX& stiffness, double activation,
                                  std::shared_ptr<const contact::RigidTool> tool) {
  std::vector<int> ids(static_cast<size_t>(stiffness.size()));
  std::iota(ids.begin(), ids.end(), 0);
  return contact::ContactBlock(std::move(ids), stiffness, activation, std::move(tool));
}

}  // namespace

LocalContact::LocalContact(contact::RigidTool tool, VecX positions, VecX stiffness, double activation,
                           const MatX& compliance, const Vec3& step_force)
    : m_tool(std::move(tool)),
      m_x0(std::move(positions)),
      m_stiffness(std::move(stiffness)),
      m_activation(activation),
      m_compliance(compliance) {
  const Eigen::Index n = 3 * m_stiffness.size();
  if (m_x0.size() != n || compliance.rows() != n || compliance.cols() != n)
    throw InvalidArgument("local contact: " + std::to_string(m_stiffness.size()) + " nodes need " + std::to_string(n) +
                          " positions and a compliance of that size");
  if (n > 0) {
    m_factor.compute(m_compliance);
    if (m_factor.info() != Eigen::Success)
      throw SolverFailure("local contact: the nodes' compliance is not positive definite (is the body held?)");
  }
  const contact::ContactBlock block =
      local_block(m_stiffness, m_activation, std::make_shared<const contact::RigidTool>(m_tool));
  VecX g = VecX::Zero(n);
  block.add_gradient(m_x0, g);
  m_f0 = -g;
  m_held = step_force - block.tool_force(m_x0);
}

Vec3 LocalContact::force(const contact::Pose& pose, int* nodes_in_contact) const {
  auto tool = std::make_shared<contact::RigidTool>(m_tool);
  tool->set_pose(pose);
  const contact::ContactBlock block = local_block(m_stiffness, m_activation, tool);
  const Eigen::Index n = m_x0.size();
  // One caller at a time: each starts from the last one's solution.
  const std::lock_guard lock(m_mutex);
  VecX x = m_last.size() == n ? m_last : m_x0;
  block.push_out(x, 0.5 * m_activation);  // an admissible start: the barrier is finite there
  // Phi and its gradient at x.
  const auto phi = [&](const VecX& at, VecX& g) {
    const VecX d = at - m_x0;
    g = m_factor.solve(d) + m_f0;
    const double e = 0.5 * d.dot(g + m_f0);  // 1/2 d^T K d + f0^T d
    return e + block.energy_and_add_gradient(at, g);
  };
  // Converged when no node's force is out of balance by more than 1e-3 of kappa dhat, the barrier's force scale per
  // node (E times its area): the force on the tool is then within 1e-3 of the exact one (tests).
  const double tolerance = 1e-3 * m_stiffness.maxCoeff() * m_activation;
  VecX g(n), g_next(n);
  double e = phi(x, g), residual = g.lpNorm<Eigen::Infinity>();
  std::vector<std::pair<int, Mat3>> blocks;
  // The direction: Newton's with each touching node's Hessian block reduced to its stiffest direction, H_p ~ l_p v_p
  // v_p^T (the barrier's normal stiffness; the tangential curvature of a curved tool, smaller by about dhat over its
  // radius, left out), solved through C by Woodbury's identity with U = S V:
  //   (K + U L U^T)^-1 g = C g - W (L^-1 + U^T W)^-1 W^T g,  W = C U,
  // an a x a Cholesky for a touching nodes (a fraction of a millisecond where the exact 3a x 3a system took several).
  std::vector<int> used;
  std::vector<Vec3> v;
  std::vector<double> l;
  MatX w, small;
  Eigen::LLT<MatX> llt;
  for (int iteration = 0; iteration < 50 && residual >= tolerance && n > 0 && std::isfinite(e); ++iteration) {
    blocks.clear();
    block.node_hessians(x, false, blocks);
    used.clear();
    v.clear();
    l.clear();
    for (const auto& [node, h] : blocks) {
      Eigen::SelfAdjointEigenSolver<Mat3> eig;
      eig.computeDirect(h);
      if (!(eig.eigenvalues()(2) > 0.0)) continue;
      used.push_back(node);
      v.push_back(eig.eigenvectors().col(2));
      l.push_back(eig.eigenvalues()(2));
    }
    const auto a = static_cast<Eigen::Index>(used.size());
    w.resize(n, a);
    for (Eigen::Index p = 0; p < a; ++p)
      w.col(p) = m_compliance.middleCols<3>(3 * used[static_cast<size_t>(p)]) * v[static_cast<size_t>(p)];
    small.resize(a, a);
    for (Eigen::Index p = 0; p < a; ++p) {
      for (Eigen::Index q = 0; q < a; ++q)
        small(p, q) = v[static_cast<size_t>(p)].dot(w.block<3, 1>(3 * used[static_cast<size_t>(p)], q));
      small(p, p) += 1.0 / l[static_cast<size_t>(p)];
    }
    const VecX cg = m_compliance * g;
    VecX step = -cg;
    if (a > 0 && llt.compute(small).info() == Eigen::Success) step += w * llt.solve(w.transpose() * g);
    double slope = g.dot(step);
    if (!(slope < 0.0)) {  // not a descent direction (round-off): C's, which is one
      step = -cg;
      slope = g.dot(step);
    }
    if (!(slope < 0.0)) break;  // stationary
    // Backtracking: the barrier is infinite inside the tool, so a step that crosses it is never accepted.
    double alpha = 1.0;
    bool accepted = false;
    for (int k = 0; k < 40; ++k, alpha *= 0.5) {
      const double e_next = phi(x + alpha * step, g_next);
      if (std::isfinite(e_next) && e_next <= e + 1e-4 * alpha * slope) {
        accepted = true;
        e = e_next;
        break;
      }
    }
    if (!accepted) break;
    x += alpha * step;
    std::swap(g, g_next);
    residual = g.lpNorm<Eigen::Infinity>();
  }
  m_last = x;
  if (nodes_in_contact) *nodes_in_contact = block.active_count(x);
  return block.tool_force(x) + m_held;
}

}  // namespace hooke::interactive
