#include <algorithm>
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
  m_schedule = ElementSchedule(element_nodes());
}

double SpringBlock::energy(const Eigen::Ref<const VecX>& x) const {
  return m_schedule.sum([&](int s) {
    const auto [i, j] = m_pairs[static_cast<size_t>(s)];
    const double stretch = (x.segment(m_dim * i, m_dim) - x.segment(m_dim * j, m_dim)).norm() - m_rest_length(s);
    return 0.5 * m_stiffness(s) * stretch * stretch;
  });
}

namespace {

// Adds k (1 - l0/l) d, dE/dp_i of one spring with d = p_i - p_j, l = |d|, at i (and its negative at j), and returns
// the springs' energy sum k/2 (l - l0)^2 when kEnergy (0 otherwise: add_gradient's loop stays without it).
// Fixed size: no allocation.
template <int D, bool kEnergy>
double add_spring_energies_and_gradients(const std::vector<std::array<int, 2>>& pairs, const VecX& stiffness,
                                         const VecX& rest, std::span<const int> springs, const double* x,
                                         double* gradient) {
  using Vec = Eigen::Matrix<double, D, 1>;
  double energy = 0.0;
  for (int s : springs) {
    const auto [i, j] = pairs[static_cast<size_t>(s)];
    const Vec d = Vec::Map(x + D * i) - Vec::Map(x + D * j);
    const double l = d.norm();
    if constexpr (kEnergy) energy += 0.5 * stiffness(s) * (l - rest(s)) * (l - rest(s));
    const Vec g = (stiffness(s) * (1.0 - rest(s) / l)) * d;
    Vec::Map(gradient + D * i) += g;
    Vec::Map(gradient + D * j) -= g;
  }
  return energy;
}

template <int D>
void add_directions(const std::vector<std::array<int, 2>>& pairs, const VecX& stiffness, const VecX& rest,
                    std::span<const int> springs, const double* x, double* out) {
  using Vec = Eigen::Matrix<double, D, 1>;
  for (int s : springs) {
    const auto [i, j] = pairs[static_cast<size_t>(s)];
    const Vec d = Vec::Map(x + D * i) - Vec::Map(x + D * j);
    const double l = d.norm();
    if (l == 0.0) continue;
    const Vec f = (stiffness(s) * rest(s) / l) * d;
    Vec::Map(out + D * i) += f;
    Vec::Map(out + D * j) -= f;
  }
}

template <int D>
void add_spring_hessians(const std::vector<std::array<int, 2>>& pairs, const VecX& stiffness, const VecX& rest,
                         std::span<const int> springs, const double* x, const model::HessianScatter& scatter,
                         double* values, bool project_psd) {
  using Vec = Eigen::Matrix<double, D, 1>;
  using Block = Eigen::Matrix<double, D, D>;
  Eigen::Matrix<double, 2 * D, 2 * D> h;
  for (int s : springs) {
    const auto [i, j] = pairs[static_cast<size_t>(s)];
    const Vec d = Vec::Map(x + D * i) - Vec::Map(x + D * j);
    const double l = d.norm(), ratio = rest(s) / l;
    const double iso = project_psd ? std::max(0.0, 1.0 - ratio) : 1.0 - ratio;
    const Block a = stiffness(s) * (iso * Block::Identity() + (ratio / (l * l)) * d * d.transpose());
    h << a, -a, -a, a;
    scatter.add<D, 2>(s, h, values);
  }
}

}  // namespace

void SpringBlock::add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const {
  m_schedule.for_each_chunk([&](std::span<const int> springs, int) {
    if (m_dim == 3)
      add_spring_energies_and_gradients<3, false>(m_pairs, m_stiffness, m_rest_length, springs, x.data(),
                                                  gradient.data());
    else
      add_spring_energies_and_gradients<2, false>(m_pairs, m_stiffness, m_rest_length, springs, x.data(),
                                                  gradient.data());
  });
}

double SpringBlock::energy_and_add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const {
  return m_schedule.sum_chunks([&](std::span<const int> springs) {
    return m_dim == 3 ? add_spring_energies_and_gradients<3, true>(m_pairs, m_stiffness, m_rest_length, springs,
                                                                   x.data(), gradient.data())
                      : add_spring_energies_and_gradients<2, true>(m_pairs, m_stiffness, m_rest_length, springs,
                                                                   x.data(), gradient.data());
  });
}

void SpringBlock::add_rest_directions(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> out) const {
  m_schedule.for_each_chunk([&](std::span<const int> springs, int) {
    if (m_dim == 3)
      add_directions<3>(m_pairs, m_stiffness, m_rest_length, springs, x.data(), out.data());
    else
      add_directions<2>(m_pairs, m_stiffness, m_rest_length, springs, x.data(), out.data());
  });
}

RowMatXi SpringBlock::element_nodes() const {
  RowMatXi nodes(static_cast<Eigen::Index>(m_pairs.size()), 2);
  for (size_t s = 0; s < m_pairs.size(); ++s) nodes.row(static_cast<Eigen::Index>(s)) << m_pairs[s][0], m_pairs[s][1];
  return nodes;
}

void SpringBlock::add_hessian_values(const Eigen::Ref<const VecX>& x, const model::HessianScatter& scatter,
                                     double* values, bool project_psd) const {
  m_schedule.for_each_chunk([&](std::span<const int> springs, int) {
    if (m_dim == 3)
      add_spring_hessians<3>(m_pairs, m_stiffness, m_rest_length, springs, x.data(), scatter, values, project_psd);
    else
      add_spring_hessians<2>(m_pairs, m_stiffness, m_rest_length, springs, x.data(), scatter, values, project_psd);
  });
}

}  // namespace hooke::springs
