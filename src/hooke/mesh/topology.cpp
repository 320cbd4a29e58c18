#include <hooke/mesh/topology.hpp>

#include <algorithm>
#include <hooke/core/error.hpp>
#include <map>

namespace hooke::mesh {

std::vector<std::array<int, 2>> unique_edges(const Mesh& mesh) {
  std::vector<std::array<int, 2>> edges;
  const int npe = nodes_per_element(mesh.kind);
  edges.reserve(static_cast<size_t>(mesh.element_count()) * (mesh.kind == ElementKind::kTet ? 6 : npe));
  auto add = [&](int a, int b) { edges.push_back({std::min(a, b), std::max(a, b)}); };
  for (int e = 0; e < mesh.element_count(); ++e) {
    const auto v = mesh.elements.row(e);
    if (mesh.kind == ElementKind::kTet) {
      for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b) add(v(a), v(b));
    } else {
      for (int a = 0; a < npe; ++a) add(v(a), v((a + 1) % npe));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

RowMatXi boundary_facets(const Mesh& mesh) {
  if (mesh.kind == ElementKind::kSurfaceTriangle)
    throw InvalidArgument("boundary_facets: a surface mesh is itself a boundary");
  const bool tet = mesh.kind == ElementKind::kTet;
  const int npe = nodes_per_element(mesh.kind), fsize = tet ? 3 : 2;
  // Outward-oriented faces of a positive tet (0,1,2,3).
  static constexpr int kTetFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  std::map<std::array<int, 3>, std::pair<std::array<int, 3>, int>> seen;  // sorted key -> (oriented, count)
  for (int e = 0; e < mesh.element_count(); ++e) {
    const auto v = mesh.elements.row(e);
    const int nfacets = tet ? 4 : npe;
    for (int f = 0; f < nfacets; ++f) {
      std::array<int, 3> oriented{-1, -1, -1};
      if (tet) {
        for (int k = 0; k < 3; ++k) oriented[k] = v(kTetFaces[f][k]);
      } else {
        oriented[0] = v(f);
        oriented[1] = v((f + 1) % npe);
      }
      // Orientation-free key: the three entries sorted (-1 pads an edge).
      std::array<int, 3> key = oriented;
      if (key[0] > key[1]) std::swap(key[0], key[1]);
      if (key[1] > key[2]) std::swap(key[1], key[2]);
      if (key[0] > key[1]) std::swap(key[0], key[1]);
      auto [it, inserted] = seen.try_emplace(key, oriented, 0);
      ++it->second.second;
    }
  }
  std::vector<std::array<int, 3>> out;
  for (const auto& [key, value] : seen)
    if (value.second == 1) out.push_back(value.first);
  RowMatXi facets(static_cast<Eigen::Index>(out.size()), fsize);
  for (size_t i = 0; i < out.size(); ++i)
    for (int k = 0; k < fsize; ++k) facets(static_cast<Eigen::Index>(i), k) = out[i][k];
  return facets;
}

VecX facet_measures(const Mesh& mesh, const RowMatXi& facets) {
  VecX m(facets.rows());
  for (Eigen::Index f = 0; f < facets.rows(); ++f) {
    if (facets.cols() == 2) {
      m(f) = (mesh.nodes.row(facets(f, 1)) - mesh.nodes.row(facets(f, 0))).norm();
    } else {
      const Vec3 a = mesh.nodes.row(facets(f, 0)).transpose();
      const Vec3 b = mesh.nodes.row(facets(f, 1)).transpose();
      const Vec3 c = mesh.nodes.row(facets(f, 2)).transpose();
      m(f) = 0.5 * (b - a).cross(c - a).norm();
    }
  }
  return m;
}

}  // namespace hooke::mesh
