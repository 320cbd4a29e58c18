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

FrictionSmoothing friction_smoothing(double y, double eps) {
  // Shifted by eps/3 from Li et al.'s f0 so that no slip stores no energy; f0 is C^1 at eps (value eps - eps/3 = 2/3
  // eps from both sides, slope 1).
  if (y >= eps) return {y - eps / 3.0, 1.0, 0.0};
  const double r = y / eps;
  return {y * r * (1.0 - r / 3.0), r * (2.0 - r), 2.0 * (1.0 - r) / eps};
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

void ContactBlock::set_friction(const Friction& friction) {
  if (!(friction.coefficient >= 0.0 && std::isfinite(friction.coefficient)))
    throw InvalidArgument("contact: the friction coefficient must be >= 0, not " +
                          std::to_string(friction.coefficient));
  if (friction.coefficient > 0.0 && !(friction.slip > 0.0 && std::isfinite(friction.slip)))
    throw InvalidArgument("contact: friction needs a slip distance > 0 m, not " + std::to_string(friction.slip));
  m_friction->friction = friction;
  m_friction->lagged.clear();
}

void ContactBlock::lag(const Eigen::Ref<const VecX>& x) const {
  std::vector<Lagged>& lagged = m_friction->lagged;
  lagged.clear();
  const double mu = m_friction->friction.coefficient;
  if (mu == 0.0) return;
  const Pose& pose = m_tool->pose();
  for_each_touching(x, [&](std::size_t k, const SurfaceDistance& s, const Barrier& b) {
    if (!(s.distance > 0.0)) return;
    // Any orthonormal pair across the normal: the slip is measured by its length, which does not depend on the pair.
    Vec3 helper = Vec3::Zero();
    Eigen::Index axis;
    s.normal.cwiseAbs().minCoeff(&axis);
    helper(axis) = 1.0;
    Lagged l;
    l.k = static_cast<int>(k);
    l.limit = mu * m_stiffness(static_cast<Eigen::Index>(k)) * std::abs(b.slope);
    l.tangent.col(0) = s.normal.cross(helper).normalized();
    l.tangent.col(1) = s.normal.cross(l.tangent.col(0));
    l.position = x.segment<3>(3 * m_nodes[k]);
    l.touched = s.closest;
    l.tool_point = pose.rotation.transpose() * (s.closest - pose.position);
    lagged.push_back(l);
  });
}

template <class F>
void ContactBlock::for_each_slipping(const Eigen::Ref<const VecX>& x, F&& f) const {
  const Pose& pose = m_tool->pose();
  const double eps = m_friction->friction.slip;
  for (const Lagged& l : m_friction->lagged) {
    // the node's displacement over the step relative to the tool's surface point it touched (which moves with the
    // tool), in the lagged tangent plane
    const Vec3 tool_moved = pose.rotation * l.tool_point + pose.position - l.touched;
    const Eigen::Vector2d slip =
        l.tangent.transpose() * (x.segment<3>(3 * m_nodes[static_cast<std::size_t>(l.k)]) - l.position - tool_moved);
    f(l, slip, friction_smoothing(slip.norm(), eps));
  }
}

double ContactBlock::energy(const Eigen::Ref<const VecX>& x) const {
  double e = 0.0;  // +infinity once a node is at or inside the tool
  for_each_touching(x, [&](std::size_t k, const SurfaceDistance&, const Barrier& b) {
    e += m_stiffness(static_cast<Eigen::Index>(k)) * b.value;
  });
  for_each_slipping(
      x, [&](const Lagged& l, const Eigen::Vector2d&, const FrictionSmoothing& f) { e += l.limit * f.value; });
  return e;
}

namespace {

/// The friction force's direction factor: f1(y) / y (1/m), finite at y = 0 (its limit 2 / eps).
double slope_over_slip(double y, double eps) { return y < eps ? (2.0 - y / eps) / eps : 1.0 / y; }

}  // namespace

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
  const double eps = m_friction->friction.slip;
  for_each_slipping(x, [&](const Lagged& l, const Eigen::Vector2d& slip, const FrictionSmoothing& f) {
    e += l.limit * f.value;
    gradient.segment<3>(3 * m_nodes[static_cast<std::size_t>(l.k)]) +=
        l.limit * slope_over_slip(slip.norm(), eps) * (l.tangent * slip);
  });
  return e;
}

RowMatXi ContactBlock::element_nodes() const {
  RowMatXi out(static_cast<Eigen::Index>(m_nodes.size()), 1);
  for (std::size_t i = 0; i < m_nodes.size(); ++i) out(static_cast<Eigen::Index>(i), 0) = m_nodes[i];
  return out;
}

template <class F>
void ContactBlock::for_each_node_hessian(const Eigen::Ref<const VecX>& x, bool project_psd, F&& f) const {
  for_each_touching(x, [&](std::size_t k, const SurfaceDistance& s, const Barrier& b) {
    if (!(s.distance > 0.0)) return;
    const double kappa = m_stiffness(static_cast<Eigen::Index>(k));
    // kappa (b'' n n^T + b' C): b'' > 0 and b' <= 0 on (0, dhat), C positive semi-definite for convex tools. The
    // projection keeps the first part and drops the second, which is negative semi-definite.
    Mat3 h = kappa * b.curvature * s.normal * s.normal.transpose();
    if (!project_psd) h += kappa * b.slope * s.curvature;
    f(static_cast<int>(k), h);
  });
  // friction: mu lambda T (f1' u u^T / |u|^2 + f1 / |u| (I - u u^T / |u|^2)) T^T, positive semi-definite as is
  const double eps = m_friction->friction.slip;
  for_each_slipping(x, [&](const Lagged& l, const Eigen::Vector2d& slip, const FrictionSmoothing& fs) {
    const double y = slip.norm(), across = slope_over_slip(y, eps);
    Eigen::Matrix2d hu = across * Eigen::Matrix2d::Identity();
    if (y > 0.0) hu += (fs.curvature - across) * slip * slip.transpose() / (y * y);
    f(l.k, Mat3(l.limit * l.tangent * hu * l.tangent.transpose()));
  });
}

void ContactBlock::add_hessian_values(const Eigen::Ref<const VecX>& x, const model::HessianScatter& scatter,
                                      double* values, bool project_psd) const {
  for_each_node_hessian(x, project_psd, [&](int k, const Mat3& h) { scatter.add<3, 1>(k, h, values); });
}

bool ContactBlock::add_node_stiffness(const Eigen::Ref<const VecX>& x, std::vector<std::pair<int, Mat3>>& out) const {
  node_hessians(x, true, out);
  return true;
}

void ContactBlock::node_hessians(const Eigen::Ref<const VecX>& x, bool project_psd,
                                 std::vector<std::pair<int, Mat3>>& out) const {
  for_each_node_hessian(x, project_psd,
                        [&](int k, const Mat3& h) { out.emplace_back(m_nodes[static_cast<std::size_t>(k)], h); });
}

template <class F>
void ContactBlock::for_each_force_on_tool(const Eigen::Ref<const VecX>& x, F&& f) const {
  for_each_touching(x, [&](std::size_t k, const SurfaceDistance& s, const Barrier& b) {
    f(s.closest, Vec3(m_stiffness(static_cast<Eigen::Index>(k)) * b.slope * s.normal));
  });
  const Pose& pose = m_tool->pose();
  const double eps = m_friction->friction.slip;
  for_each_slipping(x, [&](const Lagged& l, const Eigen::Vector2d& slip, const FrictionSmoothing&) {
    f(Vec3(pose.rotation * l.tool_point + pose.position),
      Vec3(l.limit * slope_over_slip(slip.norm(), eps) * (l.tangent * slip)));
  });
}

Vec3 ContactBlock::tool_force(const Eigen::Ref<const VecX>& x) const {
  Vec3 sum = Vec3::Zero();
  for_each_force_on_tool(x, [&](const Vec3&, const Vec3& f) { sum += f; });
  return sum;
}

Vec3 ContactBlock::tool_torque(const Eigen::Ref<const VecX>& x) const {
  Vec3 t = Vec3::Zero();
  for_each_force_on_tool(x, [&](const Vec3& at, const Vec3& f) { t += (at - m_tool->pose().position).cross(f); });
  return t;
}

int ContactBlock::push_out(Eigen::Ref<VecX> x, double distance) const {
  int moved = 0;
  for (std::size_t k = 0; k < m_nodes.size(); ++k) {
    const int node = m_nodes[k];
    if (m_tool->signed_distance(x.segment<3>(3 * node)) >= distance) continue;
    const SurfaceDistance s = m_tool->distance(x.segment<3>(3 * node));
    const Vec3 to = s.closest + distance * s.normal;
    // The push is not a slip: a lagged node's friction measures from where it was put.
    for (Lagged& l : m_friction->lagged)
      if (l.k == static_cast<int>(k)) l.position += to - x.segment<3>(3 * node);
    x.segment<3>(3 * node) = to;
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
