#include <hooke/calibrate/detail/element_springs.hpp>
#include <hooke/core/error.hpp>
#include <string>

namespace hooke::calibrate::detail {

EdgeAccumulator::EdgeAccumulator(const mesh::Mesh& mesh) : m_mesh(mesh) {
  using mesh::ElementKind;
  switch (mesh.kind) {
    case ElementKind::kTet: m_local = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}; break;
    case ElementKind::kQuad: m_local = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}, {1, 3}}; break;
    default: m_local = {{0, 1}, {1, 2}, {2, 0}}; break;
  }
  const bool quad = mesh.kind == ElementKind::kQuad;
  for (int e = 0; e < mesh.element_count(); ++e)
    for (size_t k = 0; k < m_local.size(); ++k) {
      const int a = mesh.elements(e, m_local[k][0]), b = mesh.elements(e, m_local[k][1]);
      const std::array<int, 2> key{std::min(a, b), std::max(a, b)};
      if (m_index.emplace(key, static_cast<int>(m_pairs.size())).second) {
        m_pairs.push_back(key);
        m_diagonal.push_back(quad && k >= 4 ? 1 : 0);
      }
    }
  m_length.resize(static_cast<Eigen::Index>(m_pairs.size()));
  for (size_t s = 0; s < m_pairs.size(); ++s)
    m_length(static_cast<Eigen::Index>(s)) = (mesh.nodes.row(m_pairs[s][0]) - mesh.nodes.row(m_pairs[s][1])).norm();
  m_stiffness = VecX::Zero(m_length.size());
  m_prestress = VecX::Zero(m_length.size());
}

std::vector<int> EdgeAccumulator::element_springs(int e) const {
  std::vector<int> out;
  out.reserve(m_local.size());
  for (const auto& lp : m_local) {
    const int a = m_mesh.elements(e, lp[0]), b = m_mesh.elements(e, lp[1]);
    out.push_back(m_index.at({std::min(a, b), std::max(a, b)}));
  }
  return out;
}

SpringModel EdgeAccumulator::finish() const {
  SpringModel s;
  s.dim = m_mesh.dim();
  s.pairs = m_pairs;
  s.stiffness = m_stiffness + m_prestress;
  s.rest_length = m_length;
  for (Eigen::Index i = 0; i < s.stiffness.size(); ++i) {
    if (m_prestress(i) == 0.0) continue;
    if (!(s.stiffness(i) > 0.0))
      throw InvalidArgument("calibration gives spring " + std::to_string(m_pairs[static_cast<size_t>(i)][0]) + "-" +
                            std::to_string(m_pairs[static_cast<size_t>(i)][1]) +
                            " a non-positive stiffness with its prestress (element too distorted)");
    s.rest_length(i) = m_length(i) * m_stiffness(i) / s.stiffness(i);
  }
  return s;
}

}  // namespace hooke::calibrate::detail
