#pragma once
/// A rigid tool's surface as triangles, in its pose: what front ends draw (the viewer's instrument, a series' tool).
/// docs/contact.md.
#include <hooke/contact/rigid_tool.hpp>
#include <hooke/core/types.hpp>

namespace hooke::contact {

struct ToolSurface {
  RowMatX nodes;       ///< #V x 3, m, on the tool's surface
  RowMatXi triangles;  ///< #F x 3, counter-clockwise seen from outside
};

/// The surface of a sphere or a capsule (its cylinder and two hemispheres) with `segments` around each circle, a
/// mesh tool's own triangles, or a square of side 2 `extent` (m) of a half-space's boundary plane centred on its
/// position.
/// @param segments  >= 8 (a multiple of 4 keeps the equator: rounded up to one)
/// @throws InvalidArgument for fewer than 8 segments or a plane with extent <= 0
ToolSurface tool_surface(const RigidTool& tool, int segments = 32, double extent = 0.0);

}  // namespace hooke::contact
