#include <Eigen/Cholesky>
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
    const Eigen::LLT<MatX> llt(m_compliance);
    if (llt.info() != Eigen::Success)
      throw SolverFailure("local contact: the nodes' compliance is not positive definite (is the body held?)");
    m_stiffness_matrix = llt.solve(MatX::Identity(n, n));
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
  VecX x = m_x0;
  block.push_out(x, 0.5 * m_activation);  // an admissible start: the barrier is finite there
  // Phi and its gradient at x.
  const auto phi = [&](const VecX& at, VecX& g) {
    const VecX d = at - m_x0;
    g = m_stiffness_matrix * d + m_f0;
    const double e = 0.5 * d.dot(g + m_f0);  // 1/2 d^T K d + f0^T d
    return e + block.energy_and_add_gradient(at, g);
  };
  VecX g(n), g_next(n);
  double e = phi(x, g);
  std::vector<std::pair<int, Mat3>> blocks;
  bool converged = false;
  for (int iteration = 0; iteration < 50 && !converged && n > 0 && std::isfinite(e); ++iteration) {
    // Newton's direction: (K + S H S^T)^-1 = C - C S H (I + S^T C S H)^-1 S^T C, H the touching nodes' blocks.
    blocks.clear();
    block.add_node_stiffness(x, blocks);
    const VecX cg = m_compliance * g;
    VecX step = -cg;
    if (!blocks.empty()) {
      const auto a = static_cast<Eigen::Index>(blocks.size());
      MatX h = MatX::Zero(3 * a, 3 * a), csa(n, 3 * a);
      VecX cg_a(3 * a);
      for (Eigen::Index p = 0; p < a; ++p) {
        const int node = blocks[static_cast<size_t>(p)].first;
        h.block<3, 3>(3 * p, 3 * p) = blocks[static_cast<size_t>(p)].second;
        csa.middleCols<3>(3 * p) = m_compliance.middleCols<3>(3 * node);
        cg_a.segment<3>(3 * p) = cg.segment<3>(3 * node);
      }
      MatX caa(3 * a, 3 * a);  // S^T C S: the touching nodes' rows of C S
      for (Eigen::Index p = 0; p < a; ++p)
        caa.middleRows<3>(3 * p) = csa.middleRows<3>(3 * blocks[static_cast<size_t>(p)].first);
      const MatX m = MatX::Identity(3 * a, 3 * a) + caa * h;
      step += csa * (h * m.partialPivLu().solve(cg_a));
    }
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
    converged = alpha * step.lpNorm<Eigen::Infinity>() < 1e-3 * m_activation;  // a thousandth of the barrier's range
  }
  if (nodes_in_contact) *nodes_in_contact = block.active_count(x);
  return block.tool_force(x) + m_held;
}

}  // namespace hooke::interactive
