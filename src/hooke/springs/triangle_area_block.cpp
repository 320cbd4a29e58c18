#include <hooke/core/detail/psd.hpp>
#include <hooke/core/error.hpp>
#include <hooke/springs/triangle_area_block.hpp>

namespace hooke::springs {
namespace {

using Mat23 = Eigen::Matrix<double, 2, 3>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

Mat23 corners(const Eigen::Ref<const VecX>& x, const RowMatXi& triangles, int t) {
  Mat23 p;
  for (int a = 0; a < 3; ++a) p.col(a) = x.segment<2>(2 * triangles(t, a));
  return p;
}

double cross2(const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); }

double area(const Mat23& p) { return 0.5 * cross2(p.col(1) - p.col(0), p.col(2) - p.col(0)); }

// dA/dp_a in column a: for the corners (a, b, c) in cyclic order, A = (p_b - p_a) x (p_c - p_a) / 2 is linear in
// p_a with dA/dp_a = (y_b - y_c, x_c - x_b) / 2.
Mat23 area_gradient(const Mat23& p) {
  Mat23 g;
  for (int a = 0; a < 3; ++a) {
    const Eigen::Vector2d& b = p.col((a + 1) % 3);
    const Eigen::Vector2d& c = p.col((a + 2) % 3);
    g.col(a) << 0.5 * (b.y() - c.y()), 0.5 * (c.x() - b.x());
  }
  return g;
}

// d2A/dx2 (6 x 6, constant): from dA/dp_a above, d(dA/dp_a)/dp_b = S / 2 for b the next corner and -S / 2 for the
// previous, S = [[0, 1], [-1, 0]] (so that d/dy_b of the x-component is 1/2).
Mat6 area_hessian() {
  Eigen::Matrix2d s;
  s << 0.0, 1.0, -1.0, 0.0;
  Mat6 h = Mat6::Zero();
  for (int a = 0; a < 3; ++a) {
    h.block<2, 2>(2 * a, 2 * ((a + 1) % 3)) = 0.5 * s;
    h.block<2, 2>(2 * a, 2 * ((a + 2) % 3)) = -0.5 * s;
  }
  return h;
}

}  // namespace

TriangleAreaBlock::TriangleAreaBlock(RowMatXi triangles, VecX stiffness, VecX rest_area)
    : m_triangles(std::move(triangles)), m_stiffness(std::move(stiffness)), m_rest_area(std::move(rest_area)) {
  if (m_triangles.cols() != 3 || m_stiffness.size() != m_triangles.rows() || m_rest_area.size() != m_triangles.rows())
    throw InvalidArgument("TriangleAreaBlock: one stiffness and one rest area per triangle");
  for (Eigen::Index t = 0; t < m_triangles.rows(); ++t)
    if (!std::isfinite(m_stiffness(t)) || !(m_rest_area(t) > 0.0) || !std::isfinite(m_rest_area(t)))
      throw InvalidArgument("triangle " + std::to_string(t) + " has a non-finite k_A or a non-positive rest area");
  m_schedule = ElementSchedule(m_triangles);
}

double TriangleAreaBlock::energy(const Eigen::Ref<const VecX>& x) const {
  return m_schedule.sum([&](int t) {
    const double c = area(corners(x, m_triangles, t)) - m_rest_area(t);
    return 0.5 * m_stiffness(t) * c * c / (m_rest_area(t) * m_rest_area(t));
  });
}

void TriangleAreaBlock::add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const {
  m_schedule.for_each_chunk([&](std::span<const int> triangles, int) {
    for (int t : triangles) {
      const Mat23 p = corners(x, m_triangles, t);
      const double a0 = m_rest_area(t);
      const Mat23 g = m_stiffness(t) * (area(p) - a0) / (a0 * a0) * area_gradient(p);
      for (int a = 0; a < 3; ++a) gradient.segment<2>(2 * m_triangles(t, a)) += g.col(a);
    }
  });
}

void TriangleAreaBlock::add_hessian_values(const Eigen::Ref<const VecX>& x, const model::HessianScatter& scatter,
                                           double* values, bool project_psd) const {
  static const Mat6 d2a = area_hessian();
  m_schedule.for_each_chunk([&](std::span<const int> triangles, int) {
    for (int t : triangles) {
      const Mat23 p = corners(x, m_triangles, t);
      const double a0 = m_rest_area(t), scale = m_stiffness(t) / (a0 * a0);
      const Mat23 grad = area_gradient(p);
      const Eigen::Map<const Eigen::Matrix<double, 6, 1>> g(grad.data());
      Mat6 h = scale * (g * g.transpose() + (area(p) - a0) * d2a);
      if (project_psd) hooke::detail::project_to_psd(h);
      scatter.add<2, 3>(t, h, values);
    }
  });
}

}  // namespace hooke::springs
