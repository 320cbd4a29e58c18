#include <algorithm>
#include <cmath>
#include <hooke/contact/contact_block.hpp>
#include <hooke/core/error.hpp>
#include <hooke/model/support.hpp>
#include <limits>
#include <string>

namespace hooke::contact {

Barrier barrier(double d, double dhat) {
  if (!(d > 0.0)) return {std::numeric_limits<double>::infinity(), 0.0, 0.0};
  if (d >= dhat) return {0.0, 0.0, 0.0};
  const double g = d - dhat, log_ratio = std::log(d / dhat);
  return {-g * g * log_ratio, -2.0 * g * log_ratio - g * g / d, -2.0 * log_ratio - 4.0 * g / d + g * g / (d * d)};
}

ContactBlock::ContactBlock(std::vector<int> nodes, VecX stiffness, double activation,
                           std::shared_ptr<const RigidTool> tool)
    : m_nodes(std::move(nodes)), m_stiffness(std::move(stiffness)), m_activation(activation), m_tool(std::move(tool)) {
  if (!m_tool) throw InvalidArgument("contact: no tool");
  if (static_cast<Eigen::Index>(m_nodes.size()) != m_stiffness.size())
    throw InvalidArgument("contact: one stiffness per node (" + std::to_string(m_nodes.size()) + " nodes, " +
                          std::to_string(m_stiffness.size()) + " stiffnesses)");
  if (!(activation > 0.0 && std::isfinite(activation)))
    throw InvalidArgument("contact: the activation distance must be > 0 m, not " + std::to_string(activation));
  for (Eigen::Index i = 0; i < m_stiffness.size(); ++i)
    if (!(m_stiffness(i) > 0.0 && std::isfinite(m_stiffness(i))))
      throw InvalidArgument("contact: node " + std::to_string(m_nodes[static_cast<std::size_t>(i)]) +
                            " has stiffness " + std::to_string(m_stiffness(i)) + " (must be > 0 N/m)");
}

template <class F>
void ContactBlock::for_each_touching(const Eigen::Ref<const VecX>& x, F&& f) const {
  for (std::size_t k = 0; k < m_nodes.size(); ++k) {
    const Vec3 p = x.segment<3>(3 * m_nodes[k]);
    if (m_tool->signed_distance(p) >= m_activation) continue;  // most nodes: no derivatives needed
    const SurfaceDistance s = m_tool->distance(p);
    f(k, s, barrier(s.distance, m_activation));
  }
}

double ContactBlock::energy(const Eigen::Ref<const VecX>& x) const {
  double e = 0.0;  // +infinity once a node is at or inside the tool
  for_each_touching(x, [&](std::size_t k, const SurfaceDistance&, const Barrier& b) {
    e += m_stiffness(static_cast<Eigen::Index>(k)) * b.value;
  });
  return e;
}

void ContactBlock::add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const {
  energy_and_add_gradient(x, gradient);
}

double ContactBlock::energy_and_add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const {
  double e = 0.0;
  for_each_touching(x, [&](std::size_t k, const SurfaceDistance& s, const Barrier& b) {
    const double kappa = m_stiffness(static_cast<Eigen::Index>(k));
    e += kappa * b.value;
    if (std::isfinite(b.value)) gradient.segment<3>(3 * m_nodes[k]) += kappa * b.slope * s.normal;
  });
  return e;
}

RowMatXi ContactBlock::element_nodes() const {
  RowMatXi out(static_cast<Eigen::Index>(m_nodes.size()), 1);
  for (std::size_t i = 0; i < m_nodes.size(); ++i) out(static_cast<Eigen::Index>(i), 0) = m_nodes[i];
  return out;
}

void ContactBlock::add_hessian_values(const Eigen::Ref<const VecX>& x, const model::HessianScatter& scatter,
                                      double* values, bool project_psd) const {
  for_each_touching(x, [&](std::size_t k, const SurfaceDistance& s, const Barrier& b) {
    if (!(s.distance > 0.0)) return;
    const double kappa = m_stiffness(static_cast<Eigen::Index>(k));
    // kappa (b'' n n^T + b' C): b'' > 0 and b' <= 0 on (0, dhat), C positive semi-definite for convex tools. The
    // projection keeps the first part and drops the second, which is negative semi-definite.
    Mat3 h = kappa * b.curvature * s.normal * s.normal.transpose();
    if (!project_psd) h += kappa * b.slope * s.curvature;
    scatter.add<3, 1>(static_cast<int>(k), h, values);
  });
}

Vec3 ContactBlock::tool_force(const Eigen::Ref<const VecX>& x) const {
  Vec3 f = Vec3::Zero();
  for_each_touching(x, [&](std::size_t k, const SurfaceDistance& s, const Barrier& b) {
    f += m_stiffness(static_cast<Eigen::Index>(k)) * b.slope * s.normal;
  });
  return f;
}

Vec3 ContactBlock::tool_torque(const Eigen::Ref<const VecX>& x) const {
  Vec3 t = Vec3::Zero();
  for_each_touching(x, [&](std::size_t k, const SurfaceDistance& s, const Barrier& b) {
    const Vec3 f = m_stiffness(static_cast<Eigen::Index>(k)) * b.slope * s.normal;
    t += (s.closest - m_tool->pose().position).cross(f);
  });
  return t;
}

int ContactBlock::push_out(Eigen::Ref<VecX> x, double distance) const {
  int moved = 0;
  for (int node : m_nodes) {
    if (m_tool->signed_distance(x.segment<3>(3 * node)) >= distance) continue;
    const SurfaceDistance s = m_tool->distance(x.segment<3>(3 * node));
    x.segment<3>(3 * node) = s.closest + distance * s.normal;
    ++moved;
  }
  return moved;
}

int ContactBlock::active_count(const Eigen::Ref<const VecX>& x) const {
  int n = 0;
  for_each_touching(x, [&](std::size_t, const SurfaceDistance&, const Barrier&) { ++n; });
  return n;
}

double ContactBlock::smallest_distance(const Eigen::Ref<const VecX>& x) const {
  double d = std::numeric_limits<double>::infinity();
  for (int node : m_nodes) d = std::min(d, m_tool->signed_distance(x.segment<3>(3 * node)));
  return d;
}

VecX contact_stiffness(double youngs_modulus, const VecX& boundary_area, double activation) {
  if (!(youngs_modulus > 0.0) || !(activation > 0.0))
    throw InvalidArgument("contact stiffness: E and the activation distance must be > 0");
  return youngs_modulus * boundary_area / activation;
}

std::unique_ptr<ContactBlock> boundary_contact(const mesh::Mesh& mesh, double youngs_modulus,
                                               std::shared_ptr<const RigidTool> tool, double activation) {
  if (mesh.dim() != 3) throw InvalidArgument("contact needs a 3D mesh (tets or a closed surface of triangles)");
  if (activation < 0.0) throw InvalidArgument("contact: the activation distance must be >= 0 m (0: automatic)");
  RowMatXi triangles;
  if (mesh.kind == mesh::ElementKind::kSurfaceTriangle)
    triangles = mesh.elements;
  else
    triangles = model::boundary_facets_with_geometry(mesh).facets;
  VecX area = VecX::Zero(mesh.node_count());
  double edges = 0.0;
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    const Vec3 a = mesh.nodes.row(triangles(f, 0)), b = mesh.nodes.row(triangles(f, 1)),
               c = mesh.nodes.row(triangles(f, 2));
    const double share = 0.5 * (b - a).cross(c - a).norm() / 3.0;
    for (int k = 0; k < 3; ++k) area(triangles(f, k)) += share;
    edges += (b - a).norm() + (c - b).norm() + (a - c).norm();
  }
  if (triangles.rows() == 0) throw InvalidArgument("contact: " + mesh.source + " has no boundary");
  if (activation == 0.0) activation = 0.01 * edges / (3.0 * static_cast<double>(triangles.rows()));
  std::vector<int> nodes;
  std::vector<double> shares;
  for (int i = 0; i < mesh.node_count(); ++i)
    if (area(i) > 0.0) nodes.push_back(i), shares.push_back(area(i));
  const VecX kappa = contact_stiffness(
      youngs_modulus, Eigen::Map<const VecX>(shares.data(), static_cast<Eigen::Index>(shares.size())), activation);
  return std::make_unique<ContactBlock>(std::move(nodes), kappa, activation, std::move(tool));
}

}  // namespace hooke::contact
