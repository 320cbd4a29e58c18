#pragma once
// The loops shared by the measure-preserving terms E = k / (2 m0^2) (m - m0)^2 of one element kind (tet volumes,
// triangle areas): `Shape` gives the element's measure m, its gradient dm/dx and its second derivative d2m/dx2 from
// the corner positions (a D x N matrix, one corner per column). Energy, gradient and Hessian per element follow:
// k (m - m0) / m0^2 dm and k / m0^2 (dm dm^T + (m - m0) d2m).
// With a Seth-Hill exponent q != 1 (seth_hill.hpp) the energy is k g_q(m / m0), whose gradient is k g' / m0 dm and
// Hessian k / m0^2 (g'' dm dm^T + m0 g' d2m); elements with k < 0 keep q = 1 (a concave barrier would have no lower
// bound).
#include <cmath>
#include <hooke/core/detail/psd.hpp>
#include <hooke/core/element_schedule.hpp>
#include <hooke/core/error.hpp>
#include <hooke/model/hessian_scatter.hpp>
#include <hooke/springs/detail/seth_hill.hpp>
#include <string>

namespace hooke::springs::detail {

template <class Shape>
class MeasureTerms {
 public:
  static constexpr int D = Shape::kDim, N = Shape::kCorners;
  using Corners = Eigen::Matrix<double, D, N>;
  using Local = Eigen::Matrix<double, D * N, D * N>;

  // @throws InvalidArgument naming the first element with a non-finite k or a non-positive m0
  MeasureTerms(RowMatXi elements, VecX stiffness, VecX rest, const char* what, double exponent = 1.0)
      : m_elements(std::move(elements)),
        m_stiffness(std::move(stiffness)),
        m_rest(std::move(rest)),
        m_exponent(exponent) {
    if (!std::isfinite(exponent)) throw InvalidArgument(std::string(what) + ": the term law's exponent must be finite");
    if (m_elements.cols() != N || m_stiffness.size() != m_elements.rows() || m_rest.size() != m_elements.rows())
      throw InvalidArgument(std::string(what) + ": one stiffness and one rest measure per element");
    for (Eigen::Index e = 0; e < m_elements.rows(); ++e)
      if (!std::isfinite(m_stiffness(e)) || !(m_rest(e) > 0.0) || !std::isfinite(m_rest(e)))
        throw InvalidArgument(std::string(what) + " " + std::to_string(e) +
                              " has a non-finite stiffness or a non-positive rest measure");
    m_schedule = ElementSchedule(m_elements);
    m_scale = m_stiffness.cwiseQuotient(m_rest.cwiseAbs2());
  }

  const RowMatXi& elements() const { return m_elements; }
  double exponent() const { return m_exponent; }

  double energy(const Eigen::Ref<const VecX>& x) const {
    if (m_exponent != 1.0)
      return m_schedule.sum([&](int e) {
        return m_stiffness(e) * seth_hill_energy(Shape::measure(corners(x, e)) / m_rest(e), law(e)).value;
      });
    return m_schedule.sum([&](int e) {
      const double c = Shape::measure(corners(x, e)) - m_rest(e);
      return 0.5 * m_stiffness(e) * c * c / (m_rest(e) * m_rest(e));
    });
  }

  void add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const {
    if (m_exponent != 1.0) {
      energy_and_add_gradient(x, gradient);
      return;
    }
    m_schedule.for_each_chunk([&](std::span<const int> elements, int) {
      for (int e : elements) {
        const Corners p = corners(x, e);
        const double m0 = m_rest(e);
        const Corners g = m_stiffness(e) * (Shape::measure(p) - m0) / (m0 * m0) * Shape::gradient(p);
        for (int a = 0; a < N; ++a) gradient.template segment<D>(D * m_elements(e, a)) += g.col(a);
      }
    });
  }

  // energy() and add_gradient() in one pass, to round-off (k / m0^2 kept per element: no division per element).
  double energy_and_add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const {
    // Per element: the energy and dE/dm at the measure m, for the quadratic term or the Seth-Hill law.
    const auto quadratic = [&](int e) {
      return [&, e](double m) {
        const double c = m - m_rest(e);
        return std::pair{0.5 * m_scale(e) * c * c, m_scale(e) * c};
      };
    };
    const auto seth_hill = [&](int e) {
      return [&, e](double m) {
        const SethHillEnergy g = seth_hill_energy(m / m_rest(e), law(e));
        return std::pair{m_stiffness(e) * g.value, m_stiffness(e) * g.first / m_rest(e)};
      };
    };
    const auto pass = [&](std::span<const int> elements, const auto& law_of) {
      double sum = 0.0;
      for (int e : elements) {
        if constexpr (requires { Shape::add_energy_and_gradient(x.data(), &m_elements(e, 0), law_of(e), nullptr); }) {
          sum += Shape::add_energy_and_gradient(x.data(), &m_elements(e, 0), law_of(e), gradient.data());
        } else {
          const Corners p = corners(x, e);
          const auto [energy, slope] = law_of(e)(Shape::measure(p));
          sum += energy;
          const Corners g = slope * Shape::gradient(p);
          for (int a = 0; a < N; ++a) gradient.template segment<D>(D * m_elements(e, a)) += g.col(a);
        }
      }
      return sum;
    };
    return m_schedule.sum_chunks([&](std::span<const int> elements) {
      return m_exponent == 1.0 ? pass(elements, quadratic) : pass(elements, seth_hill);
    });
  }

  void add_hessian_values(const Eigen::Ref<const VecX>& x, const model::HessianScatter& scatter, double* values,
                          bool project_psd) const {
    m_schedule.for_each_chunk([&](std::span<const int> elements, int) {
      for (int e : elements) {
        const Corners p = corners(x, e);
        const double m0 = m_rest(e), scale = m_stiffness(e) / (m0 * m0);
        const Corners grad = Shape::gradient(p);
        const Eigen::Map<const Eigen::Matrix<double, D * N, 1>> g(grad.data());
        Local h;
        if (m_exponent != 1.0) {
          const SethHillEnergy law_at = seth_hill_energy(Shape::measure(p) / m0, law(e));
          h = scale * (law_at.second * g * g.transpose() + m0 * law_at.first * Shape::hessian(p));
        } else {
          h = scale * (g * g.transpose() + (Shape::measure(p) - m0) * Shape::hessian(p));
        }
        if (project_psd) hooke::detail::project_to_psd(h);
        scatter.add<D, N>(e, h, values);
      }
    });
  }

 private:
  RowMatXi m_elements;
  VecX m_stiffness, m_rest;
  double m_exponent = 1.0;
  VecX m_scale;  // k / m0^2 per element, for the one-pass loop
  ElementSchedule m_schedule;

  // The exponent of element e's law: q, or 1 where k < 0.
  double law(int e) const { return m_stiffness(e) < 0.0 ? 1.0 : m_exponent; }

  Corners corners(const Eigen::Ref<const VecX>& x, int e) const {
    Corners p;
    for (int a = 0; a < N; ++a) p.col(a) = x.template segment<D>(D * m_elements(e, a));
    return p;
  }
};

}  // namespace hooke::springs::detail
