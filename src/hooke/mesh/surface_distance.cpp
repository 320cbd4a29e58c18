#include <algorithm>
#include <cmath>
#include <hooke/mesh/surface_distance.hpp>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace hooke::mesh {
namespace {

// Closest point of the triangle abc to p (Ericson, Real-Time Collision Detection, Sec. 5.1.5: the Voronoi regions
// of the nodes, edges and face), returned as the squared distance.
double squared_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return ap.squaredNorm();
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return bp.squaredNorm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return (p - (a + d1 / (d1 - d3) * ab)).squaredNorm();
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return cp.squaredNorm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return (p - (a + d2 / (d2 - d6) * ac)).squaredNorm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).squaredNorm();
  const double denominator = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denominator) + ac * (vc * denominator))).squaredNorm();
}

}  // namespace

struct SurfaceDistance::Grid {
  Vec3 origin;
  double cell = 1.0;
  std::int64_t n[3] = {1, 1, 1};
  std::unordered_map<std::int64_t, std::vector<int>> cells;
  std::int64_t index(const Vec3& p, int c) const {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((p(c) - origin(c)) / cell)), 0, n[c] - 1);
  }
  std::int64_t key(std::int64_t i, std::int64_t j, std::int64_t k) const { return (i * n[1] + j) * n[2] + k; }
};

SurfaceDistance::SurfaceDistance(const RowMatX& nodes, const RowMatXi& triangles)
    : m_nodes(nodes), m_triangles(triangles), m_grid(new Grid) {
  auto box = [&](Eigen::Index t) {  // the triangle's bounding box
    Vec3 tlo = Vec3::Constant(std::numeric_limits<double>::max()), thi = -tlo;
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = nodes.row(triangles(t, k)).transpose();
      tlo = tlo.cwiseMin(p);
      thi = thi.cwiseMax(p);
    }
    return std::pair<Vec3, Vec3>(tlo, thi);
  };
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max()), hi = -lo;
  double extent = 0.0;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    const auto [tlo, thi] = box(t);
    lo = lo.cwiseMin(tlo);
    hi = hi.cwiseMax(thi);
    extent += (thi - tlo).maxCoeff();
  }
  Grid& g = *m_grid;
  g.origin = lo;
  g.cell = std::max({2.0 * extent / static_cast<double>(triangles.rows()), 1e-9 * (hi - lo).norm(), 1e-300});
  for (int c = 0; c < 3; ++c)
    g.n[c] = std::min<std::int64_t>(static_cast<std::int64_t>((hi(c) - lo(c)) / g.cell) + 1, 1 << 20);
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    const auto [tlo, thi] = box(t);
    for (std::int64_t i = g.index(tlo, 0); i <= g.index(thi, 0); ++i)
      for (std::int64_t j = g.index(tlo, 1); j <= g.index(thi, 1); ++j)
        for (std::int64_t k = g.index(tlo, 2); k <= g.index(thi, 2); ++k)
          g.cells[g.key(i, j, k)].push_back(static_cast<int>(t));
  }
}

SurfaceDistance::~SurfaceDistance() { delete m_grid; }

double SurfaceDistance::operator()(const Vec3& p) const {
  const Grid& g = *m_grid;
  const std::int64_t ci = g.index(p, 0), cj = g.index(p, 1), ck = g.index(p, 2);
  // Shells of cells around p's (clamped) cell, until a shell lies farther than the best distance found: a cell of
  // shell r is at least max(distance from p to its clamped cell, (r - 1) cells) away.
  Vec3 cell_lo(g.origin(0) + ci * g.cell, g.origin(1) + cj * g.cell, g.origin(2) + ck * g.cell);
  const double outside = (p - p.cwiseMax(cell_lo).cwiseMin(cell_lo + Vec3::Constant(g.cell))).norm();
  double best = std::numeric_limits<double>::infinity();
  const std::int64_t rings = std::max({g.n[0], g.n[1], g.n[2]});
  for (std::int64_t r = 0; r <= rings; ++r) {
    if (std::sqrt(best) < std::max(outside, (static_cast<double>(r) - 1.0) * g.cell)) break;
    for (std::int64_t i = ci - r; i <= ci + r; ++i)
      for (std::int64_t j = cj - r; j <= cj + r; ++j)
        for (std::int64_t k = ck - r; k <= ck + r; ++k) {
          if (std::max({std::abs(i - ci), std::abs(j - cj), std::abs(k - ck)}) != r) continue;  // the shell only
          if (i < 0 || j < 0 || k < 0 || i >= g.n[0] || j >= g.n[1] || k >= g.n[2]) continue;
          const auto it = g.cells.find(g.key(i, j, k));
          if (it == g.cells.end()) continue;
          for (const int t : it->second)
            best = std::min(best, squared_distance(p, m_nodes.row(m_triangles(t, 0)).transpose(),
                                                   m_nodes.row(m_triangles(t, 1)).transpose(),
                                                   m_nodes.row(m_triangles(t, 2)).transpose()));
        }
  }
  return std::sqrt(best);
}

double node_hausdorff_distance(const RowMatX& nodes_a, const RowMatXi& triangles_a, const RowMatX& nodes_b,
                               const RowMatXi& triangles_b) {
  auto one_way = [](const RowMatX& from_nodes, const RowMatXi& from_triangles, const SurfaceDistance& to) {
    std::vector<char> used(static_cast<size_t>(from_nodes.rows()), 0);
    for (Eigen::Index t = 0; t < from_triangles.rows(); ++t)
      for (int k = 0; k < 3; ++k) used[static_cast<size_t>(from_triangles(t, k))] = 1;
    double d = 0.0;
    for (Eigen::Index i = 0; i < from_nodes.rows(); ++i)
      if (used[static_cast<size_t>(i)]) d = std::max(d, to(from_nodes.row(i).transpose()));
    return d;
  };
  const SurfaceDistance to_a(nodes_a, triangles_a), to_b(nodes_b, triangles_b);
  return std::max(one_way(nodes_a, triangles_a, to_b), one_way(nodes_b, triangles_b, to_a));
}

}  // namespace hooke::mesh
