#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/springs/spring_block.hpp>

namespace hooke::springs {

double spring_energy(const Eigen::Ref<const VecX>& pi, const Eigen::Ref<const VecX>& pj, double stiffness,
                     double rest_length) {
  const double stretch = (pi - pj).norm() - rest_length;
  return 0.5 * stiffness * stretch * stretch;
}

VecX spring_energy_gradient(const Eigen::Ref<const VecX>& pi, const Eigen::Ref<const VecX>& pj, double stiffness,
                            double rest_length) {
  const VecX d = pi - pj;
  const double l = d.norm();
  return stiffness * (1.0 - rest_length / l) * d;
}

MatX spring_energy_hessian(const Eigen::Ref<const VecX>& pi, const Eigen::Ref<const VecX>& pj, double stiffness,
                           double rest_length) {
  const VecX d = pi - pj;
  const double l = d.norm();
  const VecX u = d / l;
  return stiffness *
         ((1.0 - rest_length / l) * MatX::Identity(d.size(), d.size()) + (rest_length / l) * u * u.transpose());
}

SpringBlock::SpringBlock(int dim, std::vector<std::array<int, 2>> pairs, VecX stiffness, VecX rest_length)
    : m_dim(dim), m_pairs(std::move(pairs)), m_stiffness(std::move(stiffness)), m_rest_length(std::move(rest_length)) {
  if (dim != 2 && dim != 3) throw InvalidArgument("SpringBlock: dim must be 2 or 3");
  const auto n = static_cast<Eigen::Index>(m_pairs.size());
  if (m_stiffness.size() != n || m_rest_length.size() != n)
    throw InvalidArgument("SpringBlock: one stiffness and one rest length per spring");
  for (Eigen::Index s = 0; s < n; ++s) {
    if (!(m_stiffness(s) >= 0.0) || !std::isfinite(m_stiffness(s)))
      throw InvalidArgument("spring " + std::to_string(s) + " has a negative or non-finite stiffness");
    if (!(m_rest_length(s) > 0.0))
      throw InvalidArgument("spring " + std::to_string(s) + " has a non-positive rest length");
    if (m_pairs[static_cast<size_t>(s)][0] == m_pairs[static_cast<size_t>(s)][1])
      throw InvalidArgument("spring " + std::to_string(s) + " connects a node to itself");
  }
}

double SpringBlock::energy(const Eigen::Ref<const VecX>& x) const {
  double e = 0.0;
  for (size_t s = 0; s < m_pairs.size(); ++s) {
    const auto [i, j] = m_pairs[s];
    const double l = (x.segment(m_dim * i, m_dim) - x.segment(m_dim * j, m_dim)).norm();
    const double stretch = l - m_rest_length(static_cast<Eigen::Index>(s));
    e += 0.5 * m_stiffness(static_cast<Eigen::Index>(s)) * stretch * stretch;
  }
  return e;
}

void SpringBlock::add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const {
  for (size_t s = 0; s < m_pairs.size(); ++s) {
    const auto [i, j] = m_pairs[s];
    const VecX d = x.segment(m_dim * i, m_dim) - x.segment(m_dim * j, m_dim);
    const double l = d.norm();
    const auto si = static_cast<Eigen::Index>(s);
    const VecX g = m_stiffness(si) * (1.0 - m_rest_length(si) / l) * d;
    gradient.segment(m_dim * i, m_dim) += g;
    gradient.segment(m_dim * j, m_dim) -= g;
  }
}

void SpringBlock::add_hessian(const Eigen::Ref<const VecX>& x, std::vector<Triplet>& triplets, bool project_psd) const {
  triplets.reserve(triplets.size() + m_pairs.size() * 4 * m_dim * m_dim);
  for (size_t s = 0; s < m_pairs.size(); ++s) {
    const auto [i, j] = m_pairs[s];
    const VecX d = x.segment(m_dim * i, m_dim) - x.segment(m_dim * j, m_dim);
    const double l = d.norm();
    const auto si = static_cast<Eigen::Index>(s);
    const double k = m_stiffness(si), ratio = m_rest_length(si) / l;
    const double iso = project_psd ? std::max(0.0, 1.0 - ratio) : 1.0 - ratio;
    for (int a = 0; a < m_dim; ++a)
      for (int b = 0; b < m_dim; ++b) {
        const double v = k * ((a == b ? iso : 0.0) + ratio * d(a) * d(b) / (l * l));
        triplets.emplace_back(m_dim * i + a, m_dim * i + b, v);
        triplets.emplace_back(m_dim * j + a, m_dim * j + b, v);
        triplets.emplace_back(m_dim * i + a, m_dim * j + b, -v);
        triplets.emplace_back(m_dim * j + a, m_dim * i + b, -v);
      }
  }
}

}  // namespace hooke::springs
