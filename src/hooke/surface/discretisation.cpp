#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/mesh/closed_surface.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/surface/discretisation.hpp>
#include <hooke/surface/normal_cone.hpp>
#include <limits>
#include <vector>

namespace hooke::surface {

RowMatX node_normals(const RowMatXi& triangles, const Eigen::Ref<const VecX>& x) {
  RowMatX n = RowMatX::Zero(x.size() / 3, 3);
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    const Vec3 a = x.segment<3>(3 * triangles(t, 0)), b = x.segment<3>(3 * triangles(t, 1)),
               c = x.segment<3>(3 * triangles(t, 2));
    const Vec3 area2 = (b - a).cross(c - a);  // twice the area times the unit normal
    for (int k = 0; k < 3; ++k) n.row(triangles(t, k)) += area2.transpose();
  }
  n.rowwise().normalize();
  return n;
}

Discretisation discretise(const mesh::Mesh& m, const Vec3& centre) {
  Discretisation d;
  d.centre = centre;
  const VecX x = Eigen::Map<const VecX>(m.nodes.data(), m.nodes.size());
  d.volume = mesh::enclosed_volume(m.elements, x);
  d.normals = node_normals(m.elements, x);
  d.normal_cones = node_normal_cones(m.elements, x, d.normals);
  const int n = m.node_count();
  d.radial_length.resize(n);
  d.normal_length.resize(n);
  for (int i = 0; i < n; ++i) {
    const Vec3 r = m.nodes.row(i).transpose() - centre;
    d.radial_length(i) = r.norm();
    d.normal_length(i) = r.dot(d.normals.row(i).transpose());
  }
  d.radial_volume = VecX::Zero(n);
  d.normal_volume = VecX::Zero(n);
  for (int t = 0; t < m.element_count(); ++t) {
    const Vec3 a = m.nodes.row(m.elements(t, 0)).transpose(), b = m.nodes.row(m.elements(t, 1)).transpose(),
               c = m.nodes.row(m.elements(t, 2)).transpose();
    const double cone = mesh::signed_volume(centre, a, b, c);
    for (int k = 0; k < 3; ++k) {
      const int i = m.elements(t, k);
      d.radial_volume(i) += cone;
      // Fig. 6: the same triangle seen from c_i, the foot of the node's normal line nearest to c. |.|: with a
      // strongly curved neighbourhood c_i may lie in front of a far triangle's plane; its volume still counts.
      const Vec3 ci = m.nodes.row(i).transpose() - d.normal_length(i) * d.normals.row(i).transpose();
      d.normal_volume(i) += std::abs(mesh::signed_volume(ci, a, b, c));
    }
  }
  return d;
}

namespace {

// Distance along the unit direction `dir` from `origin` to triangle (a, b, c), or infinity (Moller-Trumbore). The
// barycentric bounds are widened by 1e-9 so that a ray through a shared edge or node hits one of its triangles.
double ray_distance(const Vec3& origin, const Vec3& dir, const Vec3& a, const Vec3& b, const Vec3& c) {
  constexpr double slack = 1e-9;
  const Vec3 e1 = b - a, e2 = c - a, p = dir.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-300) return std::numeric_limits<double>::infinity();
  const Vec3 s = origin - a;
  const double u = s.dot(p) / det;
  if (u < -slack || u > 1.0 + slack) return std::numeric_limits<double>::infinity();
  const Vec3 q = s.cross(e1);
  const double v = dir.dot(q) / det;
  if (v < -slack || u + v > 1.0 + slack) return std::numeric_limits<double>::infinity();
  const double t = e2.dot(q) / det;
  return t > 0.0 ? t : std::numeric_limits<double>::infinity();
}

}  // namespace

Discretisation discretise_by_depth(const mesh::Mesh& m) {
  Discretisation d;
  d.centre = mesh::volume_centroid(m);
  const VecX x = Eigen::Map<const VecX>(m.nodes.data(), m.nodes.size());
  d.volume = mesh::enclosed_volume(m.elements, x);
  d.normals = node_normals(m.elements, x);
  d.normal_cones = node_normal_cones(m.elements, x, d.normals);
  const int n = m.node_count(), nt = m.element_count();
  d.normal_length.resize(n);
  RowMatX axis(n, 3);  // the direction from p_i to its inner point c_i
  std::vector<std::vector<int>> fans(static_cast<size_t>(n));
  for (int t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) fans[static_cast<size_t>(m.elements(t, k))].push_back(t);
  auto node = [&](int t, int k) { return Vec3(m.nodes.row(m.elements(t, k)).transpose()); };
  std::vector<int> missed;
#pragma omp parallel for schedule(dynamic, 64)
  for (int i = 0; i < n; ++i) {
    const Vec3 p = m.nodes.row(i).transpose();
    // Along the inward normal; where the ray slips out (a thin crease, whose averaged normal can point out of the
    // body), along the inward normals of the node's own triangles.
    std::vector<Vec3> candidates{-d.normals.row(i).transpose()};
    for (const int t : fans[static_cast<size_t>(i)])
      candidates.push_back(-(node(t, 1) - node(t, 0)).cross(node(t, 2) - node(t, 0)).normalized());
    double depth = std::numeric_limits<double>::infinity();
    for (size_t c = 0; c < candidates.size() && !std::isfinite(depth); ++c) {
      for (int t = 0; t < nt; ++t) {
        if (m.elements(t, 0) == i || m.elements(t, 1) == i || m.elements(t, 2) == i) continue;
        depth = std::min(depth, ray_distance(p, candidates[c], node(t, 0), node(t, 1), node(t, 2)));
      }
      axis.row(i) = candidates[c].transpose();
    }
    d.normal_length(i) = 0.5 * depth;
    if (!std::isfinite(depth)) {
#pragma omp critical
      missed.push_back(i);
    }
  }
  if (!missed.empty()) {
    const int i = *std::min_element(missed.begin(), missed.end());
    throw InvalidMesh("node " + std::to_string(i) + (m.source.empty() ? "" : " of " + m.source) +
                      ": no ray inward from it meets the surface (" + std::to_string(missed.size()) +
                      " such nodes), so the surface does not enclose it");
  }
  d.radial_length = d.normal_length;
  d.normal_volume = VecX::Zero(n);
  for (int t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const int i = m.elements(t, k);
      const Vec3 ci = m.nodes.row(i).transpose() + d.normal_length(i) * axis.row(i).transpose();
      d.normal_volume(i) += std::abs(mesh::signed_volume(ci, node(t, 0), node(t, 1), node(t, 2)));
    }
  d.radial_volume = d.normal_volume;
  return d;
}

VecX estimated_masses(const Discretisation& d, double total_mass) {
  if (!(total_mass > 0.0)) throw InvalidArgument("the object mass must be positive (kg)");
  return d.radial_volume * (total_mass / d.radial_volume.sum());
}

}  // namespace hooke::surface
