#pragma once
/// What a rigid tool's shape gives a contact energy: a point's signed distance to its surface with the distance's
/// first and second derivatives. docs/contact.md.
#include <hooke/core/types.hpp>

namespace hooke::contact {

/// A point's signed distance to a tool's surface and its derivatives in the point.
struct SurfaceDistance {
  double distance = 0.0;          ///< m; < 0 inside the tool
  Vec3 normal = Vec3::Zero();     ///< d distance / d point: the unit outward normal at the closest surface point
  Mat3 curvature = Mat3::Zero();  ///< d2 distance / d point2, 1/m (positive semi-definite for these convex shapes)
  Vec3 closest = Vec3::Zero();    ///< the closest point on the tool's surface, m
};

}  // namespace hooke::contact
