#include <algorithm>
#include <hooke/identify/force_basis.hpp>
#include <hooke/identify/stacked_forces.hpp>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace hooke::identify {
namespace {

int default_groups() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

// Below this many rows the products stay on one thread (thread start-up costs more than the work).
constexpr Eigen::Index kParallelRows = 200000;

}  // namespace

StackedForceOperator::StackedForceOperator(const ParameterLayout& layout,
                                           const std::vector<const ReferenceCase*>& cases, int groups)
    : m_layout(layout) {
  const int d = layout.dim, ns = layout.spring_count(), nt = layout.volume_count();
  const int nc = static_cast<int>(cases.size());
  m_nodes = nc ? static_cast<int>(cases.front()->positions.size() / d) : 0;
  m_rows = static_cast<Eigen::Index>(nc) * d * m_nodes;
  const int ng = std::clamp(groups > 0 ? groups : default_groups(), 1, std::max(nc, 1));
  Eigen::Index row0 = 0;
  for (int group = 0, first = 0; group < ng && first < nc; ++group) {
    Group g;
    g.first = first;
    g.count = (nc - first) / (ng - group);
    g.row0 = row0;
    const int q = g.count;
    g.stretch.resize(ns, q * d);
    if (layout.offset_count()) g.direction.resize(ns, q * d);
    g.volume.resize(nt, q * 12);
    g.free.assign(static_cast<std::size_t>(m_nodes) * q * d, 1);
    for (int cc = 0; cc < q; ++cc) {
      const ReferenceCase& c = *cases[first + cc];
      const ForceBasis basis(layout, c.positions);
      g.stretch.middleCols(cc * d, d) = basis.stretch();
      if (layout.offset_count()) g.direction.middleCols(cc * d, d) = basis.direction();
      if (nt) g.volume.middleCols(cc * 12, 12) = basis.volume();
      for (int n = 0; n < m_nodes; ++n)
        for (int k = 0; k < d; ++k)
          if (c.fixed_dofs[static_cast<std::size_t>(d * n + k)])
            g.free[static_cast<std::size_t>((n * q + cc) * d + k)] = 0;
    }
    row0 += static_cast<Eigen::Index>(m_nodes) * q * d;
    first += q;
    m_groups.push_back(std::move(g));
  }
}

Eigen::Index StackedForceOperator::row_of(int c, Eigen::Index dof) const {
  const int d = m_layout.dim;
  for (const Group& g : m_groups)
    if (c >= g.first && c < g.first + g.count) return g.row0 + ((dof / d) * g.count + (c - g.first)) * d + dof % d;
  return -1;
}

VecX StackedForceOperator::right_hand_side(const std::vector<const ReferenceCase*>& cases) const {
  VecX b = VecX::Zero(m_rows);
  for (const Group& g : m_groups)
    for (int cc = 0; cc < g.count; ++cc) {
      const ReferenceCase& c = *cases[static_cast<std::size_t>(g.first + cc)];
      for (Eigen::Index dof = 0; dof < c.external_force.size(); ++dof) {
        const Eigen::Index row = row_of(g.first + cc, dof);
        if (g.free[static_cast<std::size_t>(row - g.row0)]) b(row) = c.external_force(dof);
      }
    }
  return b;
}

void StackedForceOperator::apply_group(const Group& g, const VecX& theta, double* y) const {
  const int d = m_layout.dim, q = g.count, w = q * d, ns = m_layout.spring_count(), nt = m_layout.volume_count();
  const int offsets = ns + nt;
  std::fill(y, y + static_cast<Eigen::Index>(m_nodes) * w, 0.0);
  for (int s = 0; s < ns; ++s) {
    const auto [i, j] = m_layout.pairs[static_cast<std::size_t>(s)];
    const double k = theta(s);
    const double* a = &g.stretch(s, 0);
    double* yi = y + static_cast<Eigen::Index>(i) * w;
    double* yj = y + static_cast<Eigen::Index>(j) * w;
    for (int r = 0; r < w; ++r) {
      yj[r] += k * a[r];
      yi[r] -= k * a[r];
    }
    if (m_layout.offset_count()) {
      const double delta = theta(offsets + s);
      const double* u = &g.direction(s, 0);
      for (int r = 0; r < w; ++r) {
        yj[r] += delta * u[r];
        yi[r] -= delta * u[r];
      }
    }
  }
  for (int t = 0; t < nt; ++t) {  // volume terms exist on tets only: 3 components per node
    const double kv = theta(ns + t);
    const double* a = &g.volume(t, 0);
    for (int corner = 0; corner < 4; ++corner) {
      double* yn = y + static_cast<Eigen::Index>(m_layout.tets(t, corner)) * w;
      for (int cc = 0; cc < q; ++cc)
        for (int k = 0; k < 3; ++k) yn[3 * cc + k] += kv * a[12 * cc + 3 * corner + k];
    }
  }
  const Eigen::Index n = static_cast<Eigen::Index>(m_nodes) * w;
  for (Eigen::Index r = 0; r < n; ++r)
    if (!g.free[static_cast<std::size_t>(r)]) y[r] = 0.0;
}

void StackedForceOperator::transpose_group(const Group& g, const double* y, VecX& theta) const {
  const int d = m_layout.dim, q = g.count, w = q * d, ns = m_layout.spring_count(), nt = m_layout.volume_count();
  const int offsets = ns + nt;
  theta.setZero(cols());
  for (int s = 0; s < ns; ++s) {
    const auto [i, j] = m_layout.pairs[static_cast<std::size_t>(s)];
    const double* a = &g.stretch(s, 0);
    const double* yi = y + static_cast<Eigen::Index>(i) * w;
    const double* yj = y + static_cast<Eigen::Index>(j) * w;
    double sum = 0.0;
    for (int r = 0; r < w; ++r) sum += a[r] * (yj[r] - yi[r]);
    theta(s) = sum;
    if (m_layout.offset_count()) {
      const double* u = &g.direction(s, 0);
      double sum_u = 0.0;
      for (int r = 0; r < w; ++r) sum_u += u[r] * (yj[r] - yi[r]);
      theta(offsets + s) = sum_u;
    }
  }
  for (int t = 0; t < nt; ++t) {
    const double* a = &g.volume(t, 0);
    double sum = 0.0;
    for (int corner = 0; corner < 4; ++corner) {
      const double* yn = y + static_cast<Eigen::Index>(m_layout.tets(t, corner)) * w;
      for (int cc = 0; cc < q; ++cc)
        for (int k = 0; k < 3; ++k) sum += a[12 * cc + 3 * corner + k] * yn[3 * cc + k];
    }
    theta(ns + t) = sum;
  }
}

void StackedForceOperator::apply(const VecX& x, VecX& y) const {
  y.resize(m_rows);
  const int ng = static_cast<int>(m_groups.size());
#pragma omp parallel for schedule(static) if (m_rows > kParallelRows)
  for (int k = 0; k < ng; ++k) apply_group(m_groups[k], x, y.data() + m_groups[k].row0);
}

void StackedForceOperator::apply_transpose(const VecX& y, VecX& x) const {
  const int ng = static_cast<int>(m_groups.size());
  std::vector<VecX> parts(static_cast<std::size_t>(ng));
#pragma omp parallel for schedule(static) if (m_rows > kParallelRows)
  for (int k = 0; k < ng; ++k) {
    const Group& g = m_groups[k];
    const Eigen::Index n = static_cast<Eigen::Index>(m_nodes) * g.count * m_layout.dim;
    VecX masked(n);  // y with the supported rows zeroed
    for (Eigen::Index r = 0; r < n; ++r) masked(r) = g.free[static_cast<std::size_t>(r)] ? y(g.row0 + r) : 0.0;
    transpose_group(g, masked.data(), parts[static_cast<std::size_t>(k)]);
  }
  x.setZero(cols());
  for (const VecX& p : parts) x += p;
}

VecX StackedForceOperator::squared_column_norms() const {
  const int d = m_layout.dim, ns = m_layout.spring_count(), nt = m_layout.volume_count();
  const int offsets = ns + nt;
  VecX out = VecX::Zero(cols());
  for (const Group& g : m_groups) {
    const int w = g.count * d;
    const auto free = [&](int node, int r) { return g.free[static_cast<std::size_t>(node * w + r)] ? 1.0 : 0.0; };
    for (int s = 0; s < ns; ++s) {
      const auto [i, j] = m_layout.pairs[static_cast<std::size_t>(s)];
      for (int r = 0; r < w; ++r) {
        const double seen = free(i, r) + free(j, r);
        out(s) += seen * g.stretch(s, r) * g.stretch(s, r);
        if (m_layout.offset_count()) out(offsets + s) += seen * g.direction(s, r) * g.direction(s, r);
      }
    }
    for (int t = 0; t < nt; ++t)
      for (int corner = 0; corner < 4; ++corner)
        for (int cc = 0; cc < g.count; ++cc)
          for (int k = 0; k < 3; ++k) {
            const double a = g.volume(t, 12 * cc + 3 * corner + k);
            out(ns + t) += free(m_layout.tets(t, corner), 3 * cc + k) * a * a;
          }
  }
  return out;
}

}  // namespace hooke::identify
