#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/mesh/self_intersection.hpp>
#include <unordered_map>

namespace hooke::mesh {
namespace {

struct Triangles {
  const Mesh& mesh;
  double zero;  // |orientation| below this is 0 (m^3)

  Vec3 node(int t, int k) const { return mesh.nodes.row(mesh.elements(t, k)).transpose(); }
  int sign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) const {
    const double v = (b - a).dot((c - a).cross(d - a));
    return v > zero ? 1 : (v < -zero ? -1 : 0);
  }
  // Segment pq passes through the interior of triangle abc.
  bool crosses(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) const {
    const int sp = sign(a, b, c, p), sq = sign(a, b, c, q);
    if (sp == 0 || sq == 0 || sp == sq) return false;
    const int s0 = sign(p, q, a, b), s1 = sign(p, q, b, c), s2 = sign(p, q, c, a);
    return s0 != 0 && s0 == s1 && s1 == s2;
  }
  // An edge of s (not touching `skip`, a node index or -1) crosses t.
  bool edge_of_crosses(int s, int t, int skip) const {
    const Vec3 a = node(t, 0), b = node(t, 1), c = node(t, 2);
    for (int k = 0; k < 3; ++k) {
      const int i = mesh.elements(s, k), j = mesh.elements(s, (k + 1) % 3);
      if (i == skip || j == skip) continue;
      if (crosses(node(s, k), node(s, (k + 1) % 3), a, b, c)) return true;
    }
    return false;
  }
  bool cross(int s, int t) const {
    int shared = 0, node_shared = -1;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (mesh.elements(s, i) == mesh.elements(t, j)) {
          ++shared;
          node_shared = mesh.elements(s, i);
        }
    if (shared >= 2) return false;
    return edge_of_crosses(s, t, node_shared) || edge_of_crosses(t, s, node_shared);
  }
};

}  // namespace

std::vector<std::array<int, 2>> self_intersections(const Mesh& mesh, int max_pairs) {
  if (mesh.kind != ElementKind::kSurfaceTriangle)
    throw InvalidArgument("self_intersections needs a triangle surface, not " +
                          std::string(element_kind_name(mesh.kind)) + " elements");
  const int nt = mesh.element_count();
  std::vector<std::array<int, 2>> pairs;
  if (nt < 2) return pairs;
  const double scale = bounding_box_diagonal(mesh);
  const Triangles tri{mesh, 1e-12 * scale * scale * scale};
  // Grid cells of the mean bounding-box extent of a triangle: each triangle meets a few cells.
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> lo(nt, 3), hi(nt, 3);
  double extent = 0.0;
  for (int t = 0; t < nt; ++t) {
    const Vec3 a = tri.node(t, 0), b = tri.node(t, 1), c = tri.node(t, 2);
    lo.row(t) = a.cwiseMin(b).cwiseMin(c).transpose();
    hi.row(t) = a.cwiseMax(b).cwiseMax(c).transpose();
    extent += (hi.row(t) - lo.row(t)).maxCoeff();
  }
  const Vec3 origin = lo.colwise().minCoeff().transpose();
  const double cell = std::max(extent / nt, 1e-9 * scale);
  auto index = [&](double x, int c) { return static_cast<std::int64_t>(std::floor((x - origin(c)) / cell)); };
  auto key = [](std::int64_t i, std::int64_t j, std::int64_t k) {
    return (static_cast<std::uint64_t>(i) * 73856093u) ^ (static_cast<std::uint64_t>(j) * 19349663u) ^
           (static_cast<std::uint64_t>(k) * 83492791u);
  };
  struct Cell {
    std::int64_t i, j, k;
    std::vector<int> triangles;
  };
  std::unordered_map<std::uint64_t, std::vector<Cell>> grid;
  for (int t = 0; t < nt; ++t)
    for (std::int64_t i = index(lo(t, 0), 0); i <= index(hi(t, 0), 0); ++i)
      for (std::int64_t j = index(lo(t, 1), 1); j <= index(hi(t, 1), 1); ++j)
        for (std::int64_t k = index(lo(t, 2), 2); k <= index(hi(t, 2), 2); ++k) {
          auto& bucket = grid[key(i, j, k)];
          auto it = std::find_if(bucket.begin(), bucket.end(),
                                 [&](const Cell& c) { return c.i == i && c.j == j && c.k == k; });
          if (it == bucket.end()) {
            bucket.push_back({i, j, k, {}});
            it = bucket.end() - 1;
          }
          it->triangles.push_back(t);
        }
  for (const auto& [h, bucket] : grid)
    for (const Cell& c : bucket)
      for (size_t x = 0; x < c.triangles.size(); ++x)
        for (size_t y = x + 1; y < c.triangles.size(); ++y) {
          const int s = c.triangles[x], t = c.triangles[y];
          // Boxes apart: no crossing. Otherwise test the pair once, in the lowest cell both boxes meet.
          if ((lo.row(s).array() > hi.row(t).array()).any() || (lo.row(t).array() > hi.row(s).array()).any()) continue;
          if (c.i != index(std::max(lo(s, 0), lo(t, 0)), 0) || c.j != index(std::max(lo(s, 1), lo(t, 1)), 1) ||
              c.k != index(std::max(lo(s, 2), lo(t, 2)), 2))
            continue;
          if (tri.cross(s, t)) pairs.push_back({std::min(s, t), std::max(s, t)});
        }
  std::sort(pairs.begin(), pairs.end());
  if (pairs.size() > static_cast<size_t>(std::max(max_pairs, 0))) pairs.resize(static_cast<size_t>(max_pairs));
  return pairs;
}

void require_no_self_intersection(const Mesh& mesh) {
  const auto pairs = self_intersections(mesh, 1 << 20);
  if (pairs.empty()) return;
  throw InvalidMesh(element_label(mesh, pairs[0][0]) + " and " + element_label(mesh, pairs[0][1]) +
                        " cross each other: the surface passes through itself (" + std::to_string(pairs.size()) +
                        " crossing pairs), so it bounds no solid; repair the scan (e.g. remove the self-intersections "
                        "in a mesh editor) and try again",
                    pairs[0][0]);
}

}  // namespace hooke::mesh
