#include <algorithm>
#include <cmath>
#include <hooke/contact/triangle_shape.hpp>
#include <hooke/core/error.hpp>
#include <hooke/mesh/closed_surface.hpp>
#include <limits>
#include <map>
#include <string>
#include <utility>

namespace hooke::contact {
namespace {

// Where on a triangle the closest point lies: its interior, an edge (ab, bc, ca) or a vertex (a, b, c).
enum class Feature { kFace, kEdgeAB, kEdgeBC, kEdgeCA, kVertexA, kVertexB, kVertexC };

struct Closest {
  Vec3 point;
  Feature feature;
};

// The closest point of triangle abc to p, by the Voronoi regions of its vertices, edges and face (barycentric
// coordinates from the dot products of the edge vectors with p's offsets).
Closest closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {a, Feature::kVertexA};
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {b, Feature::kVertexB};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return {a + d1 / (d1 - d3) * ab, Feature::kEdgeAB};
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {c, Feature::kVertexC};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return {a + d2 / (d2 - d6) * ac, Feature::kEdgeCA};
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
    return {b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b), Feature::kEdgeBC};
  const double denom = 1.0 / (va + vb + vc);
  return {a + ab * (vb * denom) + ac * (vc * denom), Feature::kFace};
}

}  // namespace

TriangleShape::TriangleShape(mesh::Mesh surface, double rounding)
    : m_surface(std::move(surface)), m_rounding(rounding) {
  if (!(rounding >= 0.0 && std::isfinite(rounding)))
    throw InvalidArgument("a mesh tool's rounding must be >= 0 m, not " + std::to_string(rounding));
  m_volume = mesh::check_closed_surface(m_surface).volume;
  const RowMatX& x = m_surface.nodes;
  const RowMatXi& t = m_surface.elements;
  const auto faces = static_cast<std::size_t>(t.rows());
  m_face_normal.resize(faces);
  m_edge_normal.resize(faces);
  m_vertex_normal.assign(static_cast<std::size_t>(x.rows()), Vec3::Zero());
  std::map<std::pair<int, int>, Vec3> edge_sum;  // undirected edge -> the sum of its two faces' normals
  for (std::size_t f = 0; f < faces; ++f) {
    const auto e = static_cast<Eigen::Index>(f);
    const Vec3 p[3] = {x.row(t(e, 0)), x.row(t(e, 1)), x.row(t(e, 2))};
    const Vec3 n = (p[1] - p[0]).cross(p[2] - p[0]).normalized();
    m_face_normal[f] = n;
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = (p[(k + 1) % 3] - p[k]).normalized(), v = (p[(k + 2) % 3] - p[k]).normalized();
      m_vertex_normal[static_cast<std::size_t>(t(e, k))] += std::acos(std::clamp(u.dot(v), -1.0, 1.0)) * n;
      const int i = t(e, k), j = t(e, (k + 1) % 3);
      // try_emplace: a fixed-size Eigen vector is not zero on default construction.
      edge_sum.try_emplace({std::min(i, j), std::max(i, j)}, Vec3::Zero()).first->second += n;
    }
  }
  for (std::size_t f = 0; f < faces; ++f)
    for (int k = 0; k < 3; ++k) {
      const auto e = static_cast<Eigen::Index>(f);
      const int i = t(e, k), j = t(e, (k + 1) % 3);
      m_edge_normal[f][static_cast<std::size_t>(k)] = edge_sum.at({std::min(i, j), std::max(i, j)}).normalized();
    }
  for (Vec3& n : m_vertex_normal) n.normalize();
  m_lo = x.colwise().minCoeff().transpose();
  m_hi = x.colwise().maxCoeff().transpose();
  m_reach = 0.1 * (m_hi - m_lo).norm();
}

SurfaceDistance TriangleShape::distance(const Vec3& q) const {
  const RowMatX& x = m_surface.nodes;
  const RowMatXi& t = m_surface.elements;
  double best = std::numeric_limits<double>::infinity();
  Closest found{Vec3::Zero(), Feature::kFace};
  Eigen::Index face = 0;
  for (Eigen::Index f = 0; f < t.rows(); ++f) {
    const Closest c = closest_on_triangle(q, x.row(t(f, 0)), x.row(t(f, 1)), x.row(t(f, 2)));
    const double d2 = (q - c.point).squaredNorm();
    if (d2 < best) best = d2, found = c, face = f;
  }
  const auto fi = static_cast<std::size_t>(face);
  Vec3 pseudo;  // the feature's pseudo-normal: its sign test is exact for closed surfaces (Baerentzen & Aanaes)
  Vec3 edge = Vec3::Zero();
  switch (found.feature) {
    case Feature::kFace: pseudo = m_face_normal[fi]; break;
    case Feature::kEdgeAB:
    case Feature::kEdgeBC:
    case Feature::kEdgeCA: {
      const int k = static_cast<int>(found.feature) - static_cast<int>(Feature::kEdgeAB);
      pseudo = m_edge_normal[fi][static_cast<std::size_t>(k)];
      edge = (Vec3(x.row(t(face, (k + 1) % 3))) - Vec3(x.row(t(face, k)))).normalized();
      break;
    }
    default:
      pseudo = m_vertex_normal[static_cast<std::size_t>(
          t(face, static_cast<int>(found.feature) - static_cast<int>(Feature::kVertexA)))];
  }
  SurfaceDistance s;
  const Vec3 r = q - found.point;
  const double rho = std::sqrt(best);
  const double sign = r.dot(pseudo) >= 0.0 ? 1.0 : -1.0;
  s.distance = sign * rho - m_rounding;
  if (!(rho > 1e-12 * (m_hi - m_lo).norm())) {  // on the surface: the distance has no derivative there
    s.normal = pseudo;
    s.closest = found.point + m_rounding * pseudo;
    return s;
  }
  s.normal = sign * r / rho;
  s.closest = found.point + m_rounding * s.normal;
  // The unsigned distance to a face is flat; to an edge it curves across the edge, to a vertex in every direction.
  if (found.feature != Feature::kFace) {
    const Vec3 n = r / rho;
    s.curvature = (Mat3::Identity() - n * n.transpose() - edge * edge.transpose()) * (sign / rho);
  }
  return s;
}

double TriangleShape::signed_distance(const Vec3& q) const {
  const double box = (m_lo - q).cwiseMax(q - m_hi).cwiseMax(0.0).norm();
  if (box > m_reach + m_rounding) return box - m_rounding;
  return distance(q).distance;
}

}  // namespace hooke::contact
