#include <cmath>
#include <hooke/identify/force_basis.hpp>
#include <hooke/springs/detail/seth_hill.hpp>
#include <hooke/springs/tet_volume_block.hpp>

namespace hooke::identify {
namespace {
// A relative stretch (l/l0 - 1, V/V0 - 1) below this is round-off of the positions, not a deformation: its column is
// zero. A spring or tet whose nodes are all held and moved rigidly (an instrument's plate, displacement control) is
// unstretched up to round-off, and a column of round-off would let the least squares give it any stiffness.
constexpr double kRoundOffStretch = 1e-9;
}  // namespace

ForceBasis::ForceBasis(const ParameterLayout& layout, const Eigen::Ref<const VecX>& positions)
    : m_layout(layout), m_dim(layout.dim) {
  const int d = m_dim, ns = layout.spring_count(), nt = layout.volume_count();
  m_stretch.resize(ns, d);
  if (layout.offset_count()) m_direction.resize(ns, d);
  for (int s = 0; s < ns; ++s) {
    const auto [i, j] = layout.pairs[s];
    const VecX edge = positions.segment(d * j, d) - positions.segment(d * i, d);
    const double l = edge.norm();
    const VecX u = l > 0.0 ? VecX(edge / l) : VecX::Zero(d);
    const double l0 = layout.rest_length(s);
    if (std::abs(l / l0 - 1.0) < kRoundOffStretch) {
      m_stretch.row(s).setZero();
      if (layout.offset_count()) m_direction.row(s) = u.transpose();
      continue;
    }
    m_stretch.row(s) =
        (layout.spring_exponent == 1.0 ? l - l0
                                       : l0 * springs::detail::seth_hill_energy(l / l0, layout.spring_exponent).first) *
        u.transpose();
    if (layout.offset_count()) m_direction.row(s) = u.transpose();
  }
  m_volume.resize(nt, 12);
  for (int t = 0; t < nt; ++t) {
    Eigen::Matrix<double, 3, 4> p;
    for (int a = 0; a < 4; ++a) p.col(a) = positions.segment<3>(3 * layout.tets(t, a));
    const double v0 = layout.rest_volume(t);
    const double v = (p.col(1) - p.col(0)).dot((p.col(2) - p.col(0)).cross(p.col(3) - p.col(0))) / 6.0;
    if (std::abs(v / v0 - 1.0) < kRoundOffStretch) {
      m_volume.row(t).setZero();
      continue;
    }
    const double slope = layout.volume_exponent == 1.0
                             ? (v - v0) / (v0 * v0)
                             : springs::detail::seth_hill_energy(v / v0, layout.volume_exponent).first / v0;
    const Eigen::Matrix<double, 3, 4> g = slope * springs::tet_volume_gradient(p);
    m_volume.row(t) = Eigen::Map<const Eigen::Matrix<double, 1, 12>>(g.data());
  }
}

namespace {
template <int D>
void add_spring_forces(const ParameterLayout& layout, const RowMatX& stretch, const RowMatX& direction,
                       const Eigen::Ref<const VecX>& theta, Eigen::Ref<VecX> forces) {
  using V = Eigen::Matrix<double, D, 1>;
  const int ns = layout.spring_count(), offsets = ns + layout.volume_count();
  for (int s = 0; s < ns; ++s) {
    const auto [i, j] = layout.pairs[s];
    V f = theta(s) * stretch.row(s).transpose().template head<D>();
    if (layout.offset_count()) f += theta(offsets + s) * direction.row(s).transpose().template head<D>();
    forces.template segment<D>(D * j) += f;
    forces.template segment<D>(D * i) -= f;
  }
}
}  // namespace

void ForceBasis::apply(const Eigen::Ref<const VecX>& theta, Eigen::Ref<VecX> forces) const {
  const int ns = m_layout.spring_count(), nt = m_layout.volume_count();
  forces.setZero();
  if (m_dim == 2)
    add_spring_forces<2>(m_layout, m_stretch, m_direction, theta, forces);
  else
    add_spring_forces<3>(m_layout, m_stretch, m_direction, theta, forces);
  for (int t = 0; t < nt; ++t)
    for (int a = 0; a < 4; ++a)
      forces.segment<3>(3 * m_layout.tets(t, a)) += theta(ns + t) * m_volume.row(t).segment<3>(3 * a).transpose();
}

namespace {
template <int D>
void spring_transpose(const ParameterLayout& layout, const RowMatX& stretch, const RowMatX& direction, const VecX& r,
                      Eigen::Ref<VecX> theta_out) {
  using V = Eigen::Matrix<double, D, 1>;
  const int ns = layout.spring_count(), offsets = ns + layout.volume_count();
  for (int s = 0; s < ns; ++s) {
    const auto [i, j] = layout.pairs[s];
    const V dr = r.template segment<D>(D * j) - r.template segment<D>(D * i);
    theta_out(s) = stretch.row(s).template head<D>().dot(dr.transpose());
    if (layout.offset_count()) theta_out(offsets + s) = direction.row(s).template head<D>().dot(dr.transpose());
  }
}

double masked_norm(const std::vector<char>& mask, int offset, const double* column, int d) {
  double sum = 0.0;
  for (int c = 0; c < d; ++c)
    if (mask[offset + c]) sum += column[c] * column[c];
  return sum;
}
}  // namespace

void ForceBasis::apply_transpose(const Eigen::Ref<const VecX>& r, Eigen::Ref<VecX> theta_out) const {
  const int ns = m_layout.spring_count(), nt = m_layout.volume_count();
  if (m_dim == 2)
    spring_transpose<2>(m_layout, m_stretch, m_direction, r, theta_out);
  else
    spring_transpose<3>(m_layout, m_stretch, m_direction, r, theta_out);
  for (int t = 0; t < nt; ++t) {
    double sum = 0.0;
    for (int a = 0; a < 4; ++a)
      sum += m_volume.row(t).segment<3>(3 * a).dot(r.segment<3>(3 * m_layout.tets(t, a)).transpose());
    theta_out(ns + t) = sum;
  }
}

void ForceBasis::add_squared_column_norms(const std::vector<char>& row_mask, Eigen::Ref<VecX> out) const {
  const int d = m_dim, ns = m_layout.spring_count(), nt = m_layout.volume_count();
  for (int s = 0; s < ns; ++s) {
    const auto [i, j] = m_layout.pairs[s];
    out(s) += masked_norm(row_mask, d * j, &m_stretch(s, 0), d) + masked_norm(row_mask, d * i, &m_stretch(s, 0), d);
    if (m_layout.offset_count())
      out(ns + nt + s) +=
          masked_norm(row_mask, d * j, &m_direction(s, 0), d) + masked_norm(row_mask, d * i, &m_direction(s, 0), d);
  }
  for (int t = 0; t < nt; ++t)
    for (int a = 0; a < 4; ++a) out(ns + t) += masked_norm(row_mask, 3 * m_layout.tets(t, a), &m_volume(t, 3 * a), 3);
}

}  // namespace hooke::identify
