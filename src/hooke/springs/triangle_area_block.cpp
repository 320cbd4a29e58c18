#include <hooke/springs/detail/measure_terms.hpp>
#include <hooke/springs/triangle_area_block.hpp>

namespace hooke::springs {
namespace {

using Mat23 = Eigen::Matrix<double, 2, 3>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

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

// The triangle's signed area and its derivatives for MeasureTerms.
struct TriangleShape {
  static constexpr int kDim = 2, kCorners = 3;
  static double measure(const Mat23& p) { return area(p); }
  static Mat23 gradient(const Mat23& p) { return area_gradient(p); }
  static Mat6 hessian(const Mat23&) {
    static const Mat6 h = area_hessian();
    return h;
  }
};

}  // namespace

struct TriangleAreaBlock::Terms : detail::MeasureTerms<TriangleShape> {
  using MeasureTerms::MeasureTerms;
};

TriangleAreaBlock::TriangleAreaBlock(RowMatXi triangles, VecX stiffness, VecX rest_area, double exponent)
    : m_terms(std::make_shared<const Terms>(std::move(triangles), std::move(stiffness), std::move(rest_area),
                                            "triangle", exponent)) {}

double TriangleAreaBlock::energy_and_add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const {
  return m_terms->energy_and_add_gradient(x, gradient);
}

RowMatXi TriangleAreaBlock::element_nodes() const { return m_terms->elements(); }

double TriangleAreaBlock::energy(const Eigen::Ref<const VecX>& x) const { return m_terms->energy(x); }

void TriangleAreaBlock::add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const {
  m_terms->add_gradient(x, gradient);
}

void TriangleAreaBlock::add_hessian_values(const Eigen::Ref<const VecX>& x, const model::HessianScatter& scatter,
                                           double* values, bool project_psd) const {
  m_terms->add_hessian_values(x, scatter, values, project_psd);
}

}  // namespace hooke::springs
