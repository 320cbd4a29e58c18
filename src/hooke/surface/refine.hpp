#pragma once
/// Local refinement of a triangle surface (Arnab & Raja, Sec. Properties Estimation: "a local surface area is
/// refined and the properties are then re-estimated").
#include <hooke/mesh/mesh.hpp>

namespace hooke::surface {

/// Splits every triangle with a node within `radius` (m) of `point` into four at its edge midpoints, and closes
/// the refinement conformingly: a triangle with two split edges is split into four as well (repeated until none
/// is left), one with a single split edge into two. Midpoints stay on the flat edges, so the surface, its
/// volume and its orientation are unchanged. Nodes keep their indices; new nodes are appended.
/// @pre mesh.kind == kSurfaceTriangle, radius >= 0
mesh::Mesh refine_near(const mesh::Mesh& mesh, const Vec3& point, double radius);

}  // namespace hooke::surface
