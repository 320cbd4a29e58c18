#include <algorithm>
#include <array>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/mesh/closed_surface.hpp>
#include <hooke/mesh/surface_cleanup.hpp>
#include <map>
#include <numeric>
#include <set>
#include <vector>

namespace hooke::mesh {
namespace {

void require_surface(const Mesh& m, const char* what) {
  if (m.kind != ElementKind::kSurfaceTriangle)
    throw InvalidArgument(std::string(what) + ": needs a surface-triangle mesh, not " +
                          std::string(element_kind_name(m.kind)));
}

// `m` with only the triangles `keep` and the nodes they use, renumbered in order.
Mesh subset(const Mesh& m, const std::vector<int>& keep) {
  std::vector<int> map(static_cast<std::size_t>(m.node_count()), -1);
  int n = 0;
  for (const int t : keep)
    for (int k = 0; k < 3; ++k) {
      int& slot = map[static_cast<std::size_t>(m.elements(t, k))];
      if (slot < 0) slot = n++;
    }
  RowMatX x(n, 3);
  for (int i = 0; i < m.node_count(); ++i)
    if (map[static_cast<std::size_t>(i)] >= 0) x.row(map[static_cast<std::size_t>(i)]) = m.nodes.row(i);
  RowMatXi t(static_cast<Eigen::Index>(keep.size()), 3);
  Eigen::VectorXi region(static_cast<Eigen::Index>(keep.size()));
  for (std::size_t r = 0; r < keep.size(); ++r) {
    for (int k = 0; k < 3; ++k)
      t(static_cast<Eigen::Index>(r), k) = map[static_cast<std::size_t>(m.elements(keep[r], k))];
    region(static_cast<Eigen::Index>(r)) = m.region.size() == m.element_count() ? m.region(keep[r]) : 0;
  }
  Mesh out = make_mesh(m.kind, std::move(x), std::move(t), m.source);
  out.region = std::move(region);
  return out;
}

}  // namespace

Mesh weld_surface(const Mesh& surface, int* merged) {
  require_surface(surface, "weld_surface");
  std::map<std::array<double, 3>, int> first;
  std::vector<int> to(static_cast<std::size_t>(surface.node_count()));
  int count = 0;
  for (int i = 0; i < surface.node_count(); ++i) {
    const std::array<double, 3> p{surface.nodes(i, 0), surface.nodes(i, 1), surface.nodes(i, 2)};
    const auto [it, added] = first.emplace(p, i);
    to[static_cast<std::size_t>(i)] = it->second;
    count += !added;
  }
  if (merged) *merged = count;
  Mesh welded = surface;
  for (int t = 0; t < welded.element_count(); ++t)
    for (int k = 0; k < 3; ++k) welded.elements(t, k) = to[static_cast<std::size_t>(welded.elements(t, k))];
  std::map<std::array<int, 3>, std::vector<int>> by_nodes;  // sorted node triple -> triangles on it
  for (int t = 0; t < welded.element_count(); ++t) {
    std::array<int, 3> key{welded.elements(t, 0), welded.elements(t, 1), welded.elements(t, 2)};
    std::sort(key.begin(), key.end());
    if (key[0] == key[1] || key[1] == key[2]) continue;  // degenerate after the weld
    by_nodes[key].push_back(t);
  }
  std::vector<int> keep;
  for (const auto& [key, tris] : by_nodes)
    if (tris.size() == 1) keep.push_back(tris[0]);  // a doubled triangle is a sheet of no thickness: both go
  std::sort(keep.begin(), keep.end());
  return subset(welded, keep);
}

Mesh drop_small_pieces(const Mesh& surface, double fraction, PiecesReport* report) {
  require_surface(surface, "drop_small_pieces");
  if (!(fraction >= 0.0 && fraction <= 1.0)) throw InvalidArgument("the speck fraction must be in [0, 1]");
  const int nt = surface.element_count();
  // Pieces: triangles joined through shared nodes (union-find).
  std::vector<int> parent(static_cast<std::size_t>(surface.node_count()));
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int a) {
    while (parent[static_cast<std::size_t>(a)] != a)
      a = parent[static_cast<std::size_t>(a)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(a)])];
    return a;
  };
  for (int t = 0; t < nt; ++t)
    for (int k = 1; k < 3; ++k)
      parent[static_cast<std::size_t>(find(surface.elements(t, k)))] = find(surface.elements(t, 0));
  std::map<int, std::vector<int>> pieces;
  for (int t = 0; t < nt; ++t) pieces[find(surface.elements(t, 0))].push_back(t);
  std::vector<std::pair<double, const std::vector<int>*>> volume;
  double largest = 0.0;
  for (const auto& [root, tris] : pieces) {
    double v = 0.0;  // signed tets from the origin: the enclosed volume of a closed piece
    for (const int t : tris) {
      const Vec3 a = surface.nodes.row(surface.elements(t, 0)), b = surface.nodes.row(surface.elements(t, 1)),
                 c = surface.nodes.row(surface.elements(t, 2));
      v += a.dot(b.cross(c)) / 6.0;
    }
    volume.emplace_back(std::abs(v), &tris);
    largest = std::max(largest, std::abs(v));
  }
  PiecesReport r;
  r.pieces = static_cast<int>(pieces.size());
  std::vector<int> keep;
  for (const auto& [v, tris] : volume) {
    if (v < fraction * largest) {
      ++r.dropped;
      r.dropped_volume += v;
      continue;
    }
    r.kept_volume += v;
    keep.insert(keep.end(), tris->begin(), tris->end());
  }
  std::sort(keep.begin(), keep.end());
  if (report) *report = r;
  return r.dropped == 0 ? surface : subset(surface, keep);
}

Mesh close_small_holes(const Mesh& surface, int max_edges, HolesReport* report) {
  require_surface(surface, "close_small_holes");
  if (max_edges < 3) throw InvalidArgument("close_small_holes: a hole has at least 3 edges");
  // Directed edges of the triangles; a boundary edge a -> b has no triangle with b -> a nor another with a -> b.
  std::map<std::pair<int, int>, int> directed;
  for (int t = 0; t < surface.element_count(); ++t)
    for (int k = 0; k < 3; ++k) ++directed[{surface.elements(t, k), surface.elements(t, (k + 1) % 3)}];
  std::map<int, std::vector<int>> next;  // boundary edges by their start node
  for (const auto& [e, count] : directed)
    if (count == 1 && !directed.count({e.second, e.first})) next[e.first].push_back(e.second);
  HolesReport r;
  std::vector<Vec3> nodes;
  std::vector<std::array<int, 3>> added;
  std::set<int> used;
  for (const auto& [start, out] : next) {
    if (used.count(start)) continue;
    std::vector<int> loop{start};
    bool simple = out.size() == 1;
    int at = start;
    while (simple) {
      const auto it = next.find(at);
      if (it == next.end() || it->second.size() != 1) {
        simple = false;
        break;
      }
      at = it->second[0];
      if (at == start) break;
      if (std::find(loop.begin(), loop.end(), at) != loop.end() || loop.size() > next.size()) {
        simple = false;
        break;
      }
      loop.push_back(at);
    }
    for (const int n : loop) used.insert(n);
    if (!simple || static_cast<int>(loop.size()) > max_edges) {
      ++r.left;
      continue;
    }
    Vec3 c = Vec3::Zero();
    for (const int n : loop) c += surface.nodes.row(n).transpose();
    c /= static_cast<double>(loop.size());
    const int centre = surface.node_count() + static_cast<int>(nodes.size());
    nodes.push_back(c);
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const int a = loop[k], b = loop[(k + 1) % loop.size()];
      added.push_back({centre, b, a});  // its edge b -> a meets the boundary edge a -> b
      const Vec3 pa = surface.nodes.row(a), pb = surface.nodes.row(b);
      r.added_area += 0.5 * (pb - c).cross(pa - c).norm();
    }
    ++r.closed;
    r.largest_closed = std::max(r.largest_closed, static_cast<int>(loop.size()));
  }
  if (report) *report = r;
  if (added.empty()) return surface;
  RowMatX x(surface.node_count() + static_cast<Eigen::Index>(nodes.size()), 3);
  x.topRows(surface.node_count()) = surface.nodes;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    x.row(surface.node_count() + static_cast<Eigen::Index>(i)) = nodes[i].transpose();
  RowMatXi t(surface.element_count() + static_cast<Eigen::Index>(added.size()), 3);
  t.topRows(surface.element_count()) = surface.elements;
  for (std::size_t i = 0; i < added.size(); ++i)
    for (int k = 0; k < 3; ++k)
      t(surface.element_count() + static_cast<Eigen::Index>(i), k) = added[i][static_cast<std::size_t>(k)];
  return make_mesh(surface.kind, std::move(x), std::move(t), surface.source);
}

void taubin_smooth(Mesh& surface, int iterations) {
  require_surface(surface, "taubin_smooth");
  if (iterations < 0) throw InvalidArgument("taubin_smooth: iterations must be >= 0");
  const int n = surface.node_count();
  std::vector<std::set<int>> neighbours(static_cast<std::size_t>(n));
  for (int t = 0; t < surface.element_count(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = surface.elements(t, k), b = surface.elements(t, (k + 1) % 3);
      neighbours[static_cast<std::size_t>(a)].insert(b);
      neighbours[static_cast<std::size_t>(b)].insert(a);
    }
  RowMatX delta(n, 3);
  auto step = [&](double factor) {
    for (int i = 0; i < n; ++i) {
      const auto& nb = neighbours[static_cast<std::size_t>(i)];
      Vec3 mean = Vec3::Zero();
      for (const int j : nb) mean += surface.nodes.row(j).transpose();
      if (nb.empty()) {
        delta.row(i).setZero();
        continue;
      }
      Vec3 d = mean / static_cast<double>(nb.size()) - surface.nodes.row(i).transpose();
      delta.row(i) = d.transpose();
    }
    surface.nodes += factor * delta;
  };
  for (int it = 0; it < iterations; ++it) {
    step(0.5);
    step(-0.53);
  }
}

}  // namespace hooke::mesh
