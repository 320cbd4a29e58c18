#include <hooke/springs/detail/measure_terms.hpp>
#include <hooke/springs/tet_volume_block.hpp>

namespace hooke::springs {
namespace {

using Mat34 = Eigen::Matrix<double, 3, 4>;

// Inlined into MeasureTerms' loops (a call per tet was half their time: 26 ns per volume on the 1 089-node cylinder).
[[gnu::always_inline]] inline double volume(const Mat34& p) {
  return (p.col(1) - p.col(0)).dot((p.col(2) - p.col(0)).cross(p.col(3) - p.col(0))) / 6.0;
}

[[gnu::always_inline]] inline Mat34 volume_gradient(const Mat34& p) {
  const Vec3 e1 = p.col(1) - p.col(0), e2 = p.col(2) - p.col(0), e3 = p.col(3) - p.col(0);
  Mat34 g;
  g.col(1) = e2.cross(e3) / 6.0;
  g.col(2) = e3.cross(e1) / 6.0;
  g.col(3) = e1.cross(e2) / 6.0;
  g.col(0) = -(g.col(1) + g.col(2) + g.col(3));
  return g;
}

}  // namespace

// dV/dp_a in column a. From V = e1 . (e2 x e3) / 6 with e_k = p_{k+1} - p1: dV/dp2 = e2 x e3 / 6,
// dV/dp3 = e3 x e1 / 6, dV/dp4 = e1 x e2 / 6, dV/dp1 = -(their sum). Erratum: Lloyd App. C.2 prints
// (p2 - p4) x (p3 - p4) for p1 and (p4 - p2) x (p1 - p2) for p3, both of the wrong sign (on the unit tet the
// first gives +(1,1,1)/6, although moving p1 towards its opposite face shrinks V); see docs/methods/springs.md.
Mat34 tet_volume_gradient(const Mat34& p) { return volume_gradient(p); }

namespace {

Mat3 cross_matrix(const Vec3& v) {
  Mat3 m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// d2V/dx2 (12 x 12). With edges e_k = p_k - p_0 (k = 1, 2, 3), V = e1 . (e2 x e3) / 6 is trilinear, and
// d2V/de2 de1 = [e3]x / 6, d2V/de3 de2 = [e1]x / 6, d2V/de1 de3 = [e2]x / 6 (their transposes, -[.]x, above the
// diagonal; zero diagonal blocks). With p_0 = -(sum of the edges' derivatives), the corner blocks are cross matrices
// too: d2V/dp0 dp1 = [e2 - e3]x / 6, dp0 dp2 = [e3 - e1]x / 6, dp0 dp3 = [e1 - e2]x / 6, dp0 dp0 = 0. Written
// block by block (the product S^T H_e S with the 9 x 12 edge map S took most of an assembly: 0.37 s on 345 000 tets).
Mat12 volume_hessian(const Mat34& p) {
  const Vec3 e1 = p.col(1) - p.col(0), e2 = p.col(2) - p.col(0), e3 = p.col(3) - p.col(0);
  Mat12 h = Mat12::Zero();
  auto pair = [&](int a, int b, const Vec3& w) {  // block (a, b) = [w]x / 6, block (b, a) its transpose
    const Mat3 m = cross_matrix(w / 6.0);
    h.block<3, 3>(3 * a, 3 * b) = m;
    h.block<3, 3>(3 * b, 3 * a) = -m;
  };
  pair(2, 1, e3);
  pair(3, 2, e1);
  pair(1, 3, e2);
  pair(0, 1, e2 - e3);
  pair(0, 2, e3 - e1);
  pair(0, 3, e1 - e2);
  return h;
}

}  // namespace

namespace {

// The tet's volume and its derivatives for MeasureTerms.
struct TetShape {
  static constexpr int kDim = 3, kCorners = 4;
  [[gnu::always_inline]] static double measure(const Mat34& p) { return volume(p); }
  [[gnu::always_inline]] static Mat34 gradient(const Mat34& p) { return volume_gradient(p); }
  static Mat12 hessian(const Mat34& p) { return volume_hessian(p); }
  // One term's energy, returned, and its gradient added to g (flat, node-major), on raw arrays with the edge cross
  // products shared: MeasureTerms' one-pass loop. `law(V)` gives the term's energy and dE/dV at the volume V
  // (k/(2 V0^2) (V - V0)^2 and k (V - V0) / V0^2 for the quadratic term). Written out in scalars, it takes 12 ns per
  // tet against 20 ns for the same through 3 x 4 Eigen temporaries (one thread, 1 089-node cylinder).
  template <class Law>
  [[gnu::always_inline]] static double add_energy_and_gradient(const double* x, const int* v, const Law& law,
                                                               double* g) {
    const double *p0 = x + 3 * v[0], *p1 = x + 3 * v[1], *p2 = x + 3 * v[2], *p3 = x + 3 * v[3];
    const double e1[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
    const double e2[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
    const double e3[3] = {p3[0] - p0[0], p3[1] - p0[1], p3[2] - p0[2]};
    const double c1[3] = {e2[1] * e3[2] - e2[2] * e3[1], e2[2] * e3[0] - e2[0] * e3[2], e2[0] * e3[1] - e2[1] * e3[0]};
    const double c2[3] = {e3[1] * e1[2] - e3[2] * e1[1], e3[2] * e1[0] - e3[0] * e1[2], e3[0] * e1[1] - e3[1] * e1[0]};
    const double c3[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    constexpr double sixth = 1.0 / 6.0;
    const auto [energy, slope] = law((e1[0] * c1[0] + e1[1] * c1[1] + e1[2] * c1[2]) * sixth);
    const double f = slope * sixth;  // dE/dV dV/dp = dE/dV * (the cross products / 6)
    double *g0 = g + 3 * v[0], *g1 = g + 3 * v[1], *g2 = g + 3 * v[2], *g3 = g + 3 * v[3];
    for (int a = 0; a < 3; ++a) {
      g1[a] += f * c1[a];
      g2[a] += f * c2[a];
      g3[a] += f * c3[a];
      g0[a] -= f * (c1[a] + c2[a] + c3[a]);
    }
    return energy;
  }
};

}  // namespace

struct TetVolumeBlock::Terms : detail::MeasureTerms<TetShape> {
  using MeasureTerms::MeasureTerms;
};

TetVolumeBlock::TetVolumeBlock(RowMatXi tets, VecX stiffness, VecX rest_volume, double exponent)
    : m_terms(std::make_shared<const Terms>(std::move(tets), std::move(stiffness), std::move(rest_volume), "tet",
                                            exponent)) {}

double TetVolumeBlock::exponent() const { return m_terms->exponent(); }

double TetVolumeBlock::energy_and_add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const {
  return m_terms->energy_and_add_gradient(x, gradient);
}

RowMatXi TetVolumeBlock::element_nodes() const { return m_terms->elements(); }

double TetVolumeBlock::energy(const Eigen::Ref<const VecX>& x) const { return m_terms->energy(x); }

void TetVolumeBlock::add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const {
  m_terms->add_gradient(x, gradient);
}

void TetVolumeBlock::add_hessian_values(const Eigen::Ref<const VecX>& x, const model::HessianScatter& scatter,
                                        double* values, bool project_psd) const {
  m_terms->add_hessian_values(x, scatter, values, project_psd);
}

}  // namespace hooke::springs
