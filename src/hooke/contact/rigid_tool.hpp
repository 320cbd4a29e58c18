#pragma once
/// A rigid instrument or obstacle: its shape (a sphere, a capsule, a half-space, a closed triangle mesh) and its pose,
/// and the signed distance of a point to its surface with that distance's first and second derivatives (what a contact
/// energy on the distance needs for its gradient and Hessian). docs/contact.md.
#include <hooke/contact/surface_distance.hpp>
#include <hooke/contact/triangle_shape.hpp>
#include <hooke/core/types.hpp>
#include <memory>
#include <string>
#include <string_view>

namespace hooke::contact {

enum class ToolShape {
  kSphere,     ///< "sphere": radius R about the pose's position (a fingertip, a probe tip)
  kCapsule,    ///< "capsule": the points within R of a segment of length L along the pose's local z axis, centred
               ///< on its position (an instrument's shaft with a round tip)
  kHalfSpace,  ///< "plane": the points below the plane through the position with the pose's local z as outward
               ///< normal (a table, a floor: an obstacle)
  kMesh,       ///< "mesh": the solid a closed triangle surface bounds (an instrument's STL), in its own coordinates
               ///< moved by the pose (contact::TriangleShape)
};

std::string_view tool_shape_name(ToolShape shape);

/// Where a rigid body is: the position of its reference point (m) and its orientation (local to world).
struct Pose {
  Vec3 position = Vec3::Zero();
  Mat3 rotation = Mat3::Identity();
};

class RigidTool {
 public:
  /// @param shape   the kind
  /// @param radius  sphere and capsule radius, m (> 0; ignored by the half-space)
  /// @param length  capsule segment length, m (>= 0; ignored otherwise)
  /// @throws InvalidArgument for a non-finite or out-of-range size
  RigidTool(ToolShape shape, double radius = 0.0, double length = 0.0);
  /// A mesh tool: the closed triangle surface `shape` (its coordinates the tool's own, m).
  /// @throws InvalidArgument for a null shape
  explicit RigidTool(std::shared_ptr<const TriangleShape> shape);

  ToolShape shape() const { return m_shape; }
  double radius() const { return m_radius; }
  double length() const { return m_length; }
  const Pose& pose() const { return m_pose; }
  /// Moves the tool (m; a rotation matrix). Not thread-safe with distance(): set it between solves or steps.
  /// @throws InvalidArgument for a non-finite position or a matrix that is not a rotation (|R^T R - I| > 1e-9)
  void set_pose(const Pose& pose);

  /// The signed distance of `point` (m) to the surface with its derivatives. Where the derivatives are not defined
  /// (the point on a sphere's centre or a capsule's axis) the normal is the pose's local z and the curvature zero.
  SurfaceDistance distance(const Vec3& point) const;
  /// distance(point).distance alone, m (no derivatives: what a contact block tests every node with).
  double signed_distance(const Vec3& point) const;

  /// "sphere:R", "capsule:R,L", "plane" (radius, length in m) or "mesh:SOURCE[,ROUNDING]".
  std::string description() const;
  /// The mesh tool's shape (null for the others).
  const TriangleShape* triangles() const { return m_triangles.get(); }

 private:
  ToolShape m_shape;
  double m_radius, m_length;
  std::shared_ptr<const TriangleShape> m_triangles;  // kMesh
  Pose m_pose;
};

/// Parses "sphere:R", "capsule:R,L", "plane" (R, L in metres times `metres_per_unit`) or "mesh:FILE[,ROUNDING]" (a
/// closed triangle surface in any mesh format io::read_mesh reads, its coordinates and the rounding radius
/// (TriangleShape) times `metres_per_unit`).
/// @throws InvalidArgument naming the text and the forms accepted; what io::read_mesh and
///   mesh::check_closed_surface throw for the file
RigidTool parse_tool(std::string_view text, double metres_per_unit = 1.0);

/// A rotation whose local z axis is `normal` (any length > 0): how a plane's outward normal or a capsule's axis is
/// given. @throws InvalidArgument for a zero or non-finite vector
Mat3 rotation_to(const Vec3& normal);

/// Parses an obstacle: "plane:X,Y,Z" (a horizontal floor through that point, outward normal +z),
/// "plane:X,Y,Z,NX,NY,NZ" (through the point, with that outward normal; coordinates in m) or "mesh:FILE[,ROUNDING]"
/// (a closed triangle surface where the file puts it, its coordinates and rounding times `metres_per_unit`).
/// @throws InvalidArgument naming the text and the forms accepted; what parse_tool throws for a mesh
RigidTool parse_obstacle(std::string_view text, double metres_per_unit = 1.0);

}  // namespace hooke::contact
