#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/core/log.hpp>
#include <hooke/mesh/closed_surface.hpp>
#include <hooke/mesh/measure.hpp>
#include <unordered_map>
#include <vector>

namespace hooke::mesh {
namespace {

std::string where(const Mesh& m) { return m.source.empty() ? std::string() : " of " + m.source; }

std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
  return (hi << 32) | lo;
}

// The two triangles of every undirected edge, or an InvalidMesh naming an open or over-shared edge.
std::unordered_map<std::uint64_t, std::array<int, 2>> edge_triangles(const Mesh& m) {
  std::unordered_map<std::uint64_t, std::array<int, 2>> edges;
  std::unordered_map<std::uint64_t, int> count;
  edges.reserve(static_cast<size_t>(3 * m.element_count()));
  for (int t = 0; t < m.element_count(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = m.elements(t, k), b = m.elements(t, (k + 1) % 3);
      const std::uint64_t key = edge_key(a, b);
      const int n = count[key]++;
      if (n >= 2)
        throw InvalidMesh("edge (" + std::to_string(std::min(a, b)) + ", " + std::to_string(std::max(a, b)) + ")" +
                              where(m) + " is shared by three or more triangles (" + std::to_string(edges[key][0]) +
                              ", " + std::to_string(edges[key][1]) + ", " + std::to_string(t) +
                              "): the surface is not manifold",
                          t);
      edges[key][static_cast<size_t>(n)] = t;
    }
  for (const auto& [key, n] : count)
    if (n == 1) {
      const int t = edges[key][0];
      throw InvalidMesh("edge (" + std::to_string(key & 0xffffffffu) + ", " + std::to_string(key >> 32) + ")" +
                            where(m) + " belongs to triangle " + std::to_string(t) +
                            " only: the surface has a hole (it must be closed)",
                        t);
    }
  return edges;
}

// Each node's triangles must form one closed fan: the edges opposite the node form a single cycle.
void require_single_fans(const Mesh& m) {
  std::vector<std::vector<std::array<int, 2>>> link(static_cast<size_t>(m.node_count()));
  for (int t = 0; t < m.element_count(); ++t)
    for (int k = 0; k < 3; ++k)
      link[static_cast<size_t>(m.elements(t, k))].push_back({m.elements(t, (k + 1) % 3), m.elements(t, (k + 2) % 3)});
  for (int v = 0; v < m.node_count(); ++v) {
    const auto& edges = link[static_cast<size_t>(v)];
    if (edges.empty())
      throw InvalidMesh("node " + std::to_string(v) + where(m) +
                        " belongs to no triangle: remove it (every node of a surface needs a normal, and a mass in the "
                        "surface model)");
    // Walk the cycle from the first link edge; it must visit every link edge.
    std::vector<char> used(edges.size(), 0);
    used[0] = 1;
    size_t visited = 1;
    int current = edges[0][1];
    const int start = edges[0][0];
    while (current != start) {
      bool found = false;
      for (size_t e = 0; e < edges.size() && !found; ++e)
        if (!used[e] && (edges[e][0] == current || edges[e][1] == current)) {
          used[e] = 1;
          ++visited;
          current = edges[e][0] == current ? edges[e][1] : edges[e][0];
          found = true;
        }
      if (!found) break;
    }
    if (visited != edges.size() || current != start)
      throw InvalidMesh("node " + std::to_string(v) + where(m) +
                        " joins two or more separate fans of triangles: the surface is not manifold there");
  }
}

}  // namespace

SurfaceCheckReport check_closed_surface(Mesh& m) {
  if (m.kind != ElementKind::kSurfaceTriangle)
    throw InvalidMesh("a closed triangle surface is needed; " + (m.source.empty() ? "the mesh" : m.source) + " holds " +
                      std::string(element_kind_name(m.kind)) + " elements");
  if (m.element_count() < 4) throw InvalidMesh("the surface" + where(m) + " has fewer than 4 triangles: not closed");
  const auto edges = edge_triangles(m);
  require_single_fans(m);
  SurfaceCheckReport report;
  // Orientation: neighbours must run through their shared edge in opposite directions. Breadth-first from
  // triangle 0, flipping a neighbour that disagrees; a visited one that disagrees means no orientation exists.
  auto runs = [&](int t, int a, int b) {
    for (int k = 0; k < 3; ++k)
      if (m.elements(t, k) == a && m.elements(t, (k + 1) % 3) == b) return true;
    return false;
  };
  std::vector<char> seen(static_cast<size_t>(m.element_count()), 0);
  std::vector<int> queue{0};
  seen[0] = 1;
  for (size_t q = 0; q < queue.size(); ++q) {
    const int t = queue[q];
    for (int k = 0; k < 3; ++k) {
      const int a = m.elements(t, k), b = m.elements(t, (k + 1) % 3);
      const auto& pair = edges.at(edge_key(a, b));
      const int u = pair[0] == t ? pair[1] : pair[0];
      const bool agrees = runs(u, b, a);
      if (seen[static_cast<size_t>(u)]) {
        if (!agrees)
          throw InvalidMesh("triangles " + std::to_string(t) + " and " + std::to_string(u) + where(m) +
                                " cannot be oriented consistently: the surface is not orientable",
                            u);
        continue;
      }
      if (!agrees) {
        std::swap(m.elements(u, 1), m.elements(u, 2));
        ++report.flipped_triangles;
      }
      seen[static_cast<size_t>(u)] = 1;
      queue.push_back(u);
    }
  }
  if (queue.size() != static_cast<size_t>(m.element_count())) {
    const auto first = std::find(seen.begin(), seen.end(), 0) - seen.begin();
    throw InvalidMesh("the surface" + where(m) + " has several separate pieces (triangle " + std::to_string(first) +
                          " is not connected to triangle 0); one closed body is needed",
                      first);
  }
  const VecX x = Eigen::Map<const VecX>(m.nodes.data(), m.nodes.size());
  double volume = enclosed_volume(m.elements, x);
  const double size = bounding_box_diagonal(m);
  if (!(std::abs(volume) > 1e-12 * size * size * size))
    throw InvalidMesh("the surface" + where(m) + " encloses no volume (" + std::to_string(volume) + " m^3)");
  if (volume < 0.0) {
    for (int t = 0; t < m.element_count(); ++t) std::swap(m.elements(t, 1), m.elements(t, 2));
    report.reversed_all = true;
    volume = -volume;
  }
  if (report.flipped_triangles > 0)
    log_warning("reoriented " + std::to_string(report.flipped_triangles) + " triangles" + where(m) +
                " to agree with their neighbours");
  if (report.reversed_all) log_warning("the surface" + where(m) + " was oriented inwards; reversed it");
  report.volume = volume;
  return report;
}

double enclosed_volume(const RowMatXi& triangles, const Eigen::Ref<const VecX>& x) {
  double v = 0.0;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    const Vec3 a = x.segment<3>(3 * triangles(t, 0)), b = x.segment<3>(3 * triangles(t, 1)),
               c = x.segment<3>(3 * triangles(t, 2));
    v += a.dot(b.cross(c)) / 6.0;
  }
  return v;
}

Vec3 volume_centroid(const Mesh& m) {
  // Centroid of the signed tets (origin, a, b, c) weighted by their volumes; shifted to the bounding-box
  // centre first so that round-off does not grow with the distance to the origin.
  const Vec3 shift = 0.5 * (m.nodes.colwise().minCoeff() + m.nodes.colwise().maxCoeff()).transpose();
  Vec3 moment = Vec3::Zero();
  double volume = 0.0;
  for (int t = 0; t < m.element_count(); ++t) {
    const Vec3 a = m.nodes.row(m.elements(t, 0)).transpose() - shift,
               b = m.nodes.row(m.elements(t, 1)).transpose() - shift,
               c = m.nodes.row(m.elements(t, 2)).transpose() - shift;
    const double v = a.dot(b.cross(c)) / 6.0;
    volume += v;
    moment += v * (a + b + c) / 4.0;
  }
  return shift + moment / volume;
}

}  // namespace hooke::mesh
