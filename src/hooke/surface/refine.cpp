#include <array>
#include <hooke/core/error.hpp>
#include <hooke/surface/refine.hpp>
#include <map>
#include <vector>

namespace hooke::surface {

mesh::Mesh refine_near(const mesh::Mesh& m, const Vec3& point, double radius) {
  if (m.kind != mesh::ElementKind::kSurfaceTriangle) throw InvalidArgument("refine_near needs a triangle surface");
  auto key = [](int a, int b) { return std::array<int, 2>{std::min(a, b), std::max(a, b)}; };
  std::map<std::array<int, 2>, int> split;  // marked edge -> midpoint node (-1 until created)
  for (int t = 0; t < m.element_count(); ++t) {
    bool near = false;
    for (int k = 0; k < 3; ++k) near = near || (m.nodes.row(m.elements(t, k)).transpose() - point).norm() <= radius;
    if (near)
      for (int k = 0; k < 3; ++k) split[key(m.elements(t, k), m.elements(t, (k + 1) % 3))] = -1;
  }
  for (bool changed = true; changed;) {
    changed = false;
    for (int t = 0; t < m.element_count(); ++t) {
      int marked = 0;
      for (int k = 0; k < 3; ++k) marked += split.count(key(m.elements(t, k), m.elements(t, (k + 1) % 3))) > 0;
      if (marked == 2) {
        for (int k = 0; k < 3; ++k) split.emplace(key(m.elements(t, k), m.elements(t, (k + 1) % 3)), -1);
        changed = true;
      }
    }
  }
  std::vector<Vec3> added;
  int next = m.node_count();
  for (auto& [edge, node] : split) {
    node = next++;
    added.push_back(0.5 * (m.nodes.row(edge[0]) + m.nodes.row(edge[1])).transpose());
  }
  std::vector<std::array<int, 3>> tris;
  for (int t = 0; t < m.element_count(); ++t) {
    const int v[3] = {m.elements(t, 0), m.elements(t, 1), m.elements(t, 2)};
    int mid[3];  // midpoint of edge (v[k], v[k+1]) or -1
    int marked = 0;
    for (int k = 0; k < 3; ++k) {
      const auto it = split.find(key(v[k], v[(k + 1) % 3]));
      mid[k] = it == split.end() ? -1 : it->second;
      marked += mid[k] >= 0;
    }
    if (marked == 0) {
      tris.push_back({v[0], v[1], v[2]});
    } else if (marked == 3) {
      tris.push_back({v[0], mid[0], mid[2]});
      tris.push_back({mid[0], v[1], mid[1]});
      tris.push_back({mid[2], mid[1], v[2]});
      tris.push_back({mid[0], mid[1], mid[2]});
    } else {
      int k = 0;
      while (mid[k] < 0) ++k;
      const int a = v[k], b = v[(k + 1) % 3], c = v[(k + 2) % 3];
      tris.push_back({a, mid[k], c});
      tris.push_back({mid[k], b, c});
    }
  }
  mesh::Mesh out;
  out.kind = m.kind;
  out.source = m.source.empty() ? "refined surface" : "refined " + m.source;
  out.nodes.resize(m.node_count() + static_cast<Eigen::Index>(added.size()), 3);
  out.nodes.topRows(m.node_count()) = m.nodes;
  for (size_t i = 0; i < added.size(); ++i) out.nodes.row(m.node_count() + static_cast<Eigen::Index>(i)) = added[i];
  out.elements.resize(static_cast<Eigen::Index>(tris.size()), 3);
  for (size_t t = 0; t < tris.size(); ++t)
    out.elements.row(static_cast<Eigen::Index>(t)) << tris[t][0], tris[t][1], tris[t][2];
  out.region = Eigen::VectorXi::Zero(out.elements.rows());
  return out;
}

}  // namespace hooke::surface
