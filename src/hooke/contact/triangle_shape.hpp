#pragma once
/// A closed triangle surface as a rigid tool's shape (an instrument's STL): the signed distance of a point to it with
/// its gradient and Hessian, the sign from the angle-weighted pseudo-normal of the closest feature (Baerentzen &
/// Aanaes 2005, "Signed distance computation using the angle weighted pseudonormal", IEEE TVCG 11(3)). In the
/// shape's own coordinates; contact::RigidTool applies the pose. docs/contact.md.
#include <hooke/contact/surface_distance.hpp>
#include <hooke/mesh/mesh.hpp>

namespace hooke::contact {

class TriangleShape {
 public:
  /// @param surface   a closed surface of triangles (mesh::check_closed_surface is applied: reoriented outwards), m
  /// @param rounding  the solid is the surface's inside grown by this much (m, >= 0): its edges and corners rounded
  ///                  with this radius. A node meeting a sharp corner balances on a point (the distance's curvature
  ///                  there is 1/d, d ~ the contact distance), which Newton's steps handle badly; a rounding of an
  ///                  edge's length or so keeps that curvature at 1/rounding (docs/contact.md).
  /// @throws InvalidMesh as check_closed_surface, naming surface.source; InvalidArgument for a negative rounding
  explicit TriangleShape(mesh::Mesh surface, double rounding = 0.0);

  /// The signed distance of `point` (m, the shape's coordinates; < 0 inside), its gradient (unit, outward), its
  /// Hessian (0 beside a face, (I - n n^T - e e^T) / |d| beside an edge of direction e, (I - n n^T) / |d| beside a
  /// vertex) and the closest surface point. Brute force over the triangles.
  SurfaceDistance distance(const Vec3& point) const;
  /// distance(point).distance where the point is within a tenth of the bounding box's diagonal of the box; farther,
  /// its distance to the box (a lower bound): what a contact block's test "beyond the activation distance?" needs.
  double signed_distance(const Vec3& point) const;

  const mesh::Mesh& surface() const { return m_surface; }
  double enclosed_volume() const { return m_volume; }  ///< m^3, of the surface (not grown by the rounding)
  double rounding() const { return m_rounding; }       ///< m

 private:
  mesh::Mesh m_surface;
  std::vector<Vec3> m_face_normal;                 // per triangle, unit
  std::vector<std::array<Vec3, 3>> m_edge_normal;  // per triangle, edges ab, bc, ca: the two faces' normals' sum
  std::vector<Vec3> m_vertex_normal;               // per node: angle-weighted sum of its faces' normals
  Vec3 m_lo = Vec3::Zero(), m_hi = Vec3::Zero();   // bounding box
  double m_reach = 0.0;                            // a tenth of its diagonal
  double m_volume = 0.0;
  double m_rounding = 0.0;
};

}  // namespace hooke::contact
