#include <hooke/mesh/validate.hpp>

#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/core/log.hpp>
#include <hooke/mesh/measure.hpp>

namespace hooke::mesh {
namespace {

double triangle_quality(double signed_area_value, double sum_sq_edges) {
  return sum_sq_edges > 0.0 ? 4.0 * std::sqrt(3.0) * signed_area_value / sum_sq_edges : 0.0;
}

Vec3 node3(const Mesh& m, int i) {
  Vec3 p = Vec3::Zero();
  for (int c = 0; c < m.dim(); ++c) p(c) = m.nodes(i, c);
  return p;
}

// Quality of the corner triangle (prev, k, next) of a quad; negative where the quad is not convex.
double quad_corner_quality(const Mesh& m, int e, int k) {
  const auto idx = m.elements.row(e);
  const Vec3 a = node3(m, idx((k + 3) % 4)), b = node3(m, idx(k)), c = node3(m, idx((k + 1) % 4));
  const double area = signed_area(a.head<2>(), b.head<2>(), c.head<2>());
  return triangle_quality(area, (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm());
}

void reverse_element(Mesh& m, int e) {
  if (m.kind == ElementKind::kQuad) {
    std::swap(m.elements(e, 1), m.elements(e, 3));
  } else {
    std::swap(m.elements(e, 1), m.elements(e, 2));
  }
}

}  // namespace

double element_quality(const Mesh& mesh, int e) {
  const auto idx = mesh.elements.row(e);
  const int n = nodes_per_element(mesh.kind);
  double sum_sq = 0.0;
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) sum_sq += (node3(mesh, idx(a)) - node3(mesh, idx(b))).squaredNorm();
  switch (mesh.kind) {
    case ElementKind::kTriangle:
    case ElementKind::kSurfaceTriangle: return triangle_quality(element_measure(mesh, e), sum_sq);
    case ElementKind::kQuad: {
      double q = 1.0;
      for (int k = 0; k < 4; ++k) q = std::min(q, quad_corner_quality(mesh, e, k));
      // A clockwise quad has all corners negative: report the sign of the orientation.
      double qmax = -1.0;
      for (int k = 0; k < 4; ++k) qmax = std::max(qmax, quad_corner_quality(mesh, e, k));
      return qmax < 0.0 ? -std::min(1.0, -qmax) : q;
    }
    case ElementKind::kTet: {
      const double l_rms = std::sqrt(sum_sq / 6.0);
      return l_rms > 0.0 ? 6.0 * std::sqrt(2.0) * element_measure(mesh, e) / (l_rms * l_rms * l_rms) : 0.0;
    }
  }
  return 0.0;
}

namespace {

// Pairs of used nodes closer than 1e-12 of the bounding-box diagonal: sorted by x, each node compared with those
// whose x is within the tolerance (O(n log n) for any mesh without long runs of equal x).
std::vector<std::array<int, 2>> coincident_nodes(const Mesh& mesh, const std::vector<char>& used) {
  std::vector<int> order;
  for (int i = 0; i < mesh.node_count(); ++i)
    if (used[static_cast<size_t>(i)]) order.push_back(i);
  std::vector<std::array<int, 2>> pairs;
  if (order.size() < 2) return pairs;
  const double tolerance = 1e-12 * (mesh.nodes.colwise().maxCoeff() - mesh.nodes.colwise().minCoeff()).norm();
  std::sort(order.begin(), order.end(), [&](int a, int b) { return mesh.nodes(a, 0) < mesh.nodes(b, 0); });
  for (size_t k = 0; k < order.size(); ++k)
    for (size_t j = k + 1; j < order.size() && mesh.nodes(order[j], 0) - mesh.nodes(order[k], 0) <= tolerance; ++j)
      if ((mesh.nodes.row(order[j]) - mesh.nodes.row(order[k])).norm() <= tolerance)
        pairs.push_back({std::min(order[k], order[j]), std::max(order[k], order[j])});
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace

ValidationReport validate(Mesh& mesh, const ValidationOptions& options) {
  ValidationReport report;
  const int nv = mesh.node_count(), ne = mesh.element_count(), npe = nodes_per_element(mesh.kind);
  const std::string where = mesh.source.empty() ? std::string("mesh") : mesh.source;
  if (mesh.nodes.cols() != mesh.dim())
    throw InvalidMesh(where + ": nodes have " + std::to_string(mesh.nodes.cols()) + " coordinates, a " +
                      std::string(element_kind_name(mesh.kind)) + " mesh needs " + std::to_string(mesh.dim()));
  if (mesh.elements.cols() != npe) throw InvalidMesh(where + ": elements have the wrong number of nodes");
  if (ne == 0) throw InvalidMesh(where + ": the mesh has no elements");
  if (mesh.region.size() != ne) mesh.region = Eigen::VectorXi::Zero(ne);
  for (int i = 0; i < nv; ++i)
    for (int c = 0; c < mesh.dim(); ++c)
      if (!std::isfinite(mesh.nodes(i, c)))
        throw InvalidMesh(where + ": node " + std::to_string(i) + " has a non-finite coordinate");

  std::vector<char> used(nv, 0);
  for (int e = 0; e < ne; ++e) {
    for (int a = 0; a < npe; ++a) {
      const int i = mesh.elements(e, a);
      if (i < 0 || i >= nv)
        throw InvalidMesh(element_label(mesh, e) + " refers to node " + std::to_string(i) + ", but there are " +
                              std::to_string(nv) + " nodes",
                          e);
      used[i] = 1;
      for (int b = 0; b < a; ++b)
        if (mesh.elements(e, b) == i)
          throw InvalidMesh(element_label(mesh, e) + " uses node " + std::to_string(i) + " twice", e);
    }
  }

  // Degenerate elements and orientation.
  int negative = 0;
  for (int e = 0; e < ne; ++e) {
    const double q = element_quality(mesh, e);
    if (std::abs(q) < options.min_quality)
      throw InvalidMesh(element_label(mesh, e) + " is degenerate (quality " + std::to_string(q) + ")", e);
    if (mesh.kind == ElementKind::kQuad && q < 0.0) {
      // Either clockwise (all corners negative) or non-convex (mixed signs).
      bool all_negative = true;
      for (int k = 0; k < 4; ++k) all_negative = all_negative && quad_corner_quality(mesh, e, k) < 0.0;
      if (!all_negative)
        throw InvalidMesh(element_label(mesh, e) + " is not convex (or its nodes are not in cyclic order)", e);
    }
    if (q < 0.0) ++negative;
  }
  if (negative > 0) {
    const bool planar = mesh.kind == ElementKind::kTriangle || mesh.kind == ElementKind::kQuad;
    const bool all_tets_negative = mesh.kind == ElementKind::kTet && negative == ne;
    if (!options.fix_orientation || (!planar && !all_tets_negative)) {
      for (int e = 0; e < ne; ++e)
        if (element_measure(mesh, e) < 0.0)
          throw InvalidMesh(element_label(mesh, e) + " is inverted (negative " +
                                (planar ? std::string("area") : std::string("volume")) + ")",
                            e);
    }
    for (int e = 0; e < ne; ++e) {
      if (element_measure(mesh, e) < 0.0) {
        reverse_element(mesh, e);
        ++report.reoriented_elements;
      }
    }
    log_warning(where + ": " + std::to_string(report.reoriented_elements) + " of " + std::to_string(ne) + " " +
                std::string(element_kind_name(mesh.kind)) +
                (planar ? " elements were clockwise; made counter-clockwise"
                        : " elements had negative volume; node order reversed"));
  }

  report.coincident_nodes = coincident_nodes(mesh, used);
  if (!report.coincident_nodes.empty()) {
    const auto [a, b] = report.coincident_nodes.front();
    log_warning(where + ": " + std::to_string(report.coincident_nodes.size()) +
                " pair(s) of nodes sit at the same point (first: nodes " + std::to_string(a) + " and " +
                std::to_string(b) + "); the mesh is cracked there, its elements on either side are not connected");
  }
  for (int i = 0; i < nv; ++i)
    if (!used[i]) report.unused_nodes.push_back(i);
  if (!report.unused_nodes.empty())
    log_warning(where + ": " + std::to_string(report.unused_nodes.size()) +
                " node(s) belong to no element (first: node " + std::to_string(report.unused_nodes.front()) +
                "); they are kept but carry no stiffness");
  return report;
}

}  // namespace hooke::mesh
