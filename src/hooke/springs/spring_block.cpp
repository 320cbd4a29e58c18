#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/springs/detail/seth_hill.hpp>
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

double seth_hill_spring_energy(const Eigen::Ref<const VecX>& pi, const Eigen::Ref<const VecX>& pj, double stiffness,
                               double rest_length, double exponent) {
  return stiffness * rest_length * rest_length *
         detail::seth_hill_energy((pi - pj).norm() / rest_length, exponent).value;
}

VecX seth_hill_spring_energy_gradient(const Eigen::Ref<const VecX>& pi, const Eigen::Ref<const VecX>& pj,
                                      double stiffness, double rest_length, double exponent) {
  const VecX d = pi - pj;
  const double l = d.norm();
  return (stiffness * rest_length * detail::seth_hill_energy(l / rest_length, exponent).first / l) * d;
}

MatX seth_hill_spring_energy_hessian(const Eigen::Ref<const VecX>& pi, const Eigen::Ref<const VecX>& pj,
                                     double stiffness, double rest_length, double exponent) {
  const VecX d = pi - pj;
  const double l = d.norm();
  const VecX u = d / l;
  const detail::SethHillEnergy g = detail::seth_hill_energy(l / rest_length, exponent);
  const MatX uu = u * u.transpose();
  return stiffness * (g.second * uu + (rest_length * g.first / l) * (MatX::Identity(d.size(), d.size()) - uu));
}

SpringBlock::SpringBlock(int dim, std::vector<std::array<int, 2>> pairs, VecX stiffness, VecX rest_length,
                         double exponent)
    : m_dim(dim),
      m_exponent(exponent),
      m_pairs(std::move(pairs)),
      m_stiffness(std::move(stiffness)),
      m_rest_length(std::move(rest_length)) {
  if (dim != 2 && dim != 3) throw InvalidArgument("SpringBlock: dim must be 2 or 3");
  if (!std::isfinite(exponent)) throw InvalidArgument("SpringBlock: the spring law's exponent must be finite");
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
    const double l = (x.segment(m_dim * i, m_dim) - x.segment(m_dim * j, m_dim)).norm(), l0 = m_rest_length(s);
    if (m_exponent != 1.0) return m_stiffness(s) * l0 * l0 * detail::seth_hill_energy(l / l0, m_exponent).value;
    const double stretch = l - l0;
    return 0.5 * m_stiffness(s) * stretch * stretch;
  });
}

namespace {

// Adds dE/dp_i of one spring at i (and its negative at j), d = p_i - p_j, l = |d|, and returns the springs' energy
// sum when kEnergy (0 otherwise: add_gradient's loop stays without it). Hookean (kHookean): k (1 - l0/l) d and
// k/2 (l - l0)^2; Seth-Hill of exponent m: k l0 g'(l / l0) d / l and k l0^2 g(l / l0). Fixed size: no allocation.
template <int D, bool kEnergy, bool kHookean>
double add_spring_energies_and_gradients(const std::vector<std::array<int, 2>>& pairs, const VecX& stiffness,
                                         const VecX& rest, double m, std::span<const int> springs, const double* x,
                                         double* gradient) {
  using Vec = Eigen::Matrix<double, D, 1>;
  double energy = 0.0;
  for (int s : springs) {
    const auto [i, j] = pairs[static_cast<size_t>(s)];
    const Vec d = Vec::Map(x + D * i) - Vec::Map(x + D * j);
    const double l = d.norm(), l0 = rest(s);
    double c = 0.0;  // dE/dp_i = c d
    if constexpr (kHookean) {
      if constexpr (kEnergy) energy += 0.5 * stiffness(s) * (l - l0) * (l - l0);
      c = stiffness(s) * (1.0 - l0 / l);
    } else {
      const detail::SethHillEnergy g = detail::seth_hill_energy(l / l0, m);
      if constexpr (kEnergy) energy += stiffness(s) * l0 * l0 * g.value;
      c = stiffness(s) * l0 * g.first / l;
    }
    const Vec f = c * d;
    Vec::Map(gradient + D * i) += f;
    Vec::Map(gradient + D * j) -= f;
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

// Hookean (kHookean): k [(1 - l0/l) I + (l0/l) u u^T], the isotropic term dropped where negative with project_psd.
// Seth-Hill of exponent m: k g'' u u^T along the spring and k l0 g' / l (I - u u^T) across it, each kept only where
// positive with project_psd.
template <int D, bool kHookean>
void add_spring_hessians(const std::vector<std::array<int, 2>>& pairs, const VecX& stiffness, const VecX& rest,
                         double m, std::span<const int> springs, const double* x, const model::HessianScatter& scatter,
                         double* values, bool project_psd) {
  using Vec = Eigen::Matrix<double, D, 1>;
  using Block = Eigen::Matrix<double, D, D>;
  Eigen::Matrix<double, 2 * D, 2 * D> h;
  for (int s : springs) {
    const auto [i, j] = pairs[static_cast<size_t>(s)];
    const Vec d = Vec::Map(x + D * i) - Vec::Map(x + D * j);
    const double l = d.norm();
    Block a;
    if constexpr (kHookean) {
      const double ratio = rest(s) / l;
      const double iso = project_psd ? std::max(0.0, 1.0 - ratio) : 1.0 - ratio;
      a = stiffness(s) * (iso * Block::Identity() + (ratio / (l * l)) * d * d.transpose());
    } else {
      const detail::SethHillEnergy g = detail::seth_hill_energy(l / rest(s), m);
      double along = stiffness(s) * g.second, across = stiffness(s) * rest(s) * g.first / l;
      if (project_psd) {
        along = std::max(0.0, along);
        across = std::max(0.0, across);
      }
      const Block uu = d * d.transpose() / (l * l);
      a = along * uu + across * (Block::Identity() - uu);
    }
    h << a, -a, -a, a;
    scatter.add<D, 2>(s, h, values);
  }
}

}  // namespace

void SpringBlock::add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const {
  if (m_exponent != 1.0) {
    energy_and_add_gradient(x, gradient);
    return;
  }
  m_schedule.for_each_chunk([&](std::span<const int> springs, int) {
    if (m_dim == 3)
      add_spring_energies_and_gradients<3, false, true>(m_pairs, m_stiffness, m_rest_length, 1.0, springs, x.data(),
                                                        gradient.data());
    else
      add_spring_energies_and_gradients<2, false, true>(m_pairs, m_stiffness, m_rest_length, 1.0, springs, x.data(),
                                                        gradient.data());
  });
}

double SpringBlock::energy_and_add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const {
  return m_schedule.sum_chunks([&](std::span<const int> springs) {
    const auto run = [&]<int D>() {
      return m_exponent == 1.0
                 ? add_spring_energies_and_gradients<D, true, true>(m_pairs, m_stiffness, m_rest_length, 1.0, springs,
                                                                    x.data(), gradient.data())
                 : add_spring_energies_and_gradients<D, true, false>(m_pairs, m_stiffness, m_rest_length, m_exponent,
                                                                     springs, x.data(), gradient.data());
    };
    return m_dim == 3 ? run.template operator()<3>() : run.template operator()<2>();
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
    const auto run = [&]<int D>() {
      if (m_exponent == 1.0)
        add_spring_hessians<D, true>(m_pairs, m_stiffness, m_rest_length, 1.0, springs, x.data(), scatter, values,
                                     project_psd);
      else
        add_spring_hessians<D, false>(m_pairs, m_stiffness, m_rest_length, m_exponent, springs, x.data(), scatter,
                                      values, project_psd);
    };
    if (m_dim == 3)
      run.template operator()<3>();
    else
      run.template operator()<2>();
  });
}

}  // namespace hooke::springs
