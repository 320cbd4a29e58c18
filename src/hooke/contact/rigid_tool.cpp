#include <algorithm>
#include <cmath>
#include <cstdio>
#include <hooke/contact/rigid_tool.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/settings.hpp>
#include <hooke/io/mesh_io.hpp>
#include <string>
#include <vector>

namespace hooke::contact {

std::string_view tool_shape_name(ToolShape shape) {
  switch (shape) {
    case ToolShape::kSphere: return "sphere";
    case ToolShape::kCapsule: return "capsule";
    case ToolShape::kHalfSpace: return "plane";
    case ToolShape::kMesh: return "mesh";
  }
  return "?";
}

RigidTool::RigidTool(ToolShape shape, double radius, double length)
    : m_shape(shape), m_radius(radius), m_length(length) {
  if (shape != ToolShape::kHalfSpace && !(radius > 0.0 && std::isfinite(radius)))
    throw InvalidArgument("a " + std::string(tool_shape_name(shape)) + " tool needs a radius > 0 m, not " +
                          std::to_string(radius));
  if (shape == ToolShape::kCapsule && !(length >= 0.0 && std::isfinite(length)))
    throw InvalidArgument("a capsule tool needs a length >= 0 m, not " + std::to_string(length));
  if (shape != ToolShape::kCapsule) m_length = 0.0;
  if (shape == ToolShape::kHalfSpace) m_radius = 0.0;
}

RigidTool::RigidTool(std::shared_ptr<const TriangleShape> shape)
    : m_shape(ToolShape::kMesh), m_radius(0.0), m_length(0.0), m_triangles(std::move(shape)) {
  if (!m_triangles) throw InvalidArgument("a mesh tool needs a triangle surface");
}

void RigidTool::set_pose(const Pose& pose) {
  if (!pose.position.allFinite()) throw InvalidArgument("a tool's position must be finite");
  if (!pose.rotation.allFinite() || (pose.rotation.transpose() * pose.rotation - Mat3::Identity()).norm() > 1e-9 ||
      pose.rotation.determinant() < 0.0)
    throw InvalidArgument("a tool's orientation must be a rotation matrix");
  m_pose = pose;
}

SurfaceDistance RigidTool::distance(const Vec3& point) const {
  if (m_shape == ToolShape::kMesh) {  // in the shape's frame, then back
    const Mat3& r = m_pose.rotation;
    SurfaceDistance s = m_triangles->distance(r.transpose() * (point - m_pose.position));
    s.normal = r * s.normal;
    s.curvature = r * s.curvature * r.transpose();
    s.closest = r * s.closest + m_pose.position;
    return s;
  }
  SurfaceDistance out;
  const Vec3 axis = m_pose.rotation.col(2);
  if (m_shape == ToolShape::kHalfSpace) {
    out.distance = axis.dot(point - m_pose.position);
    out.normal = axis;
    out.closest = point - out.distance * axis;
    return out;
  }
  // Sphere and capsule: the distance to a segment (of length 0 for the sphere) minus the radius.
  const Vec3 start = m_pose.position - 0.5 * m_length * axis;
  const double along = (point - start).dot(axis);
  const double t = std::clamp(along, 0.0, m_length);
  const Vec3 r = point - (start + t * axis);
  const double rho = r.norm();
  out.distance = rho - m_radius;
  if (!(rho > 1e-12 * m_radius)) {  // on the core: the distance has no derivative there
    out.normal = axis;
    out.closest = start + t * axis + m_radius * axis;
    return out;
  }
  out.normal = r / rho;
  out.curvature = (Mat3::Identity() - out.normal * out.normal.transpose()) / rho;
  if (m_length > 0.0 && along > 0.0 && along < m_length)  // beside the shaft: no curvature along it
    out.curvature -= axis * axis.transpose() / rho;
  out.closest = start + t * axis + m_radius * out.normal;
  return out;
}

double RigidTool::signed_distance(const Vec3& point) const {
  if (m_shape == ToolShape::kMesh)
    return m_triangles->signed_distance(m_pose.rotation.transpose() * (point - m_pose.position));
  const Vec3 axis = m_pose.rotation.col(2);
  if (m_shape == ToolShape::kHalfSpace) return axis.dot(point - m_pose.position);
  const Vec3 start = m_pose.position - 0.5 * m_length * axis;
  const double t = std::clamp((point - start).dot(axis), 0.0, m_length);
  return (point - (start + t * axis)).norm() - m_radius;
}

std::string RigidTool::description() const {
  char text[96];
  switch (m_shape) {
    case ToolShape::kSphere: std::snprintf(text, sizeof text, "sphere:%g", m_radius); break;
    case ToolShape::kCapsule: std::snprintf(text, sizeof text, "capsule:%g,%g", m_radius, m_length); break;
    case ToolShape::kHalfSpace: std::snprintf(text, sizeof text, "plane"); break;
    case ToolShape::kMesh:
      if (m_triangles->rounding() == 0.0) return "mesh:" + m_triangles->surface().source;
      std::snprintf(text, sizeof text, ",%g", m_triangles->rounding());
      return "mesh:" + m_triangles->surface().source + text;
  }
  return text;
}

RigidTool parse_tool(std::string_view text, double metres_per_unit) {
  const std::string forms = " (use sphere:R, capsule:R,L, plane or mesh:FILE[,ROUNDING]; lengths in the mesh's unit)";
  const std::size_t colon = text.find(':');
  const std::string_view kind = text.substr(0, colon);
  const std::string_view sizes = colon == std::string_view::npos ? std::string_view{} : text.substr(colon + 1);
  const std::string where = "tool '" + std::string(text) + "'";
  if (kind == "plane" && sizes.empty()) return RigidTool(ToolShape::kHalfSpace);
  if (kind == "mesh" && !sizes.empty()) {  // mesh:FILE or mesh:FILE,ROUNDING
    const std::size_t comma = sizes.rfind(',');
    const double rounding = comma == std::string_view::npos
                                ? 0.0
                                : metres_per_unit * settings::parse_number(where, sizes.substr(comma + 1));
    io::ReadOptions o;
    o.metres_per_unit = metres_per_unit;
    mesh::Mesh surface = io::read_mesh(std::string(sizes.substr(0, comma)), o);
    if (surface.kind != mesh::ElementKind::kSurfaceTriangle)
      throw InvalidArgument(where + ": " + surface.source + " is not a triangle surface");
    return RigidTool(std::make_shared<const TriangleShape>(std::move(surface), rounding));
  }
  if (kind == "sphere" && !sizes.empty())
    return RigidTool(ToolShape::kSphere, metres_per_unit * settings::parse_number(where, sizes));
  if (kind == "capsule") {
    const std::size_t comma = sizes.find(',');
    if (comma != std::string_view::npos)
      return RigidTool(ToolShape::kCapsule, metres_per_unit * settings::parse_number(where, sizes.substr(0, comma)),
                       metres_per_unit * settings::parse_number(where, sizes.substr(comma + 1)));
  }
  throw InvalidArgument("unknown " + where + forms);
}

Mat3 rotation_to(const Vec3& normal) {
  if (!normal.allFinite() || !(normal.norm() > 0.0)) throw InvalidArgument("a direction must be finite and non-zero");
  const Vec3 z = normal.normalized();
  const Vec3 helper = std::abs(z.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 x = helper.cross(z).normalized();
  Mat3 r;
  r.col(0) = x;
  r.col(1) = z.cross(x);
  r.col(2) = z;
  return r;
}

RigidTool parse_obstacle(std::string_view text, double metres_per_unit) {
  const std::string where = "obstacle '" + std::string(text) + "'";
  if (text.substr(0, 5) == "mesh:") return parse_tool(text, metres_per_unit);  // where its file puts it
  if (text.substr(0, 6) != "plane:")
    throw InvalidArgument("unknown " + where + " (use plane:X,Y,Z, plane:X,Y,Z,NX,NY,NZ (m) or mesh:FILE[,ROUNDING])");
  std::vector<double> v;
  std::string_view rest = text.substr(6);
  while (true) {
    const std::size_t comma = rest.find(',');
    v.push_back(settings::parse_number(where, rest.substr(0, comma)));
    if (comma == std::string_view::npos) break;
    rest = rest.substr(comma + 1);
  }
  if (v.size() != 3 && v.size() != 6)
    throw InvalidArgument(where + " needs 3 or 6 numbers (plane:X,Y,Z or plane:X,Y,Z,NX,NY,NZ, m)");
  RigidTool plane(ToolShape::kHalfSpace);
  const Vec3 normal = v.size() == 6 ? Vec3(v[3], v[4], v[5]) : Vec3::UnitZ();
  try {
    plane.set_pose({Vec3(v[0], v[1], v[2]), rotation_to(normal)});
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(where + ": " + e.what());
  }
  return plane;
}

}  // namespace hooke::contact
