#pragma once
/// Signed element measures: area of a planar triangle or quad, volume of a tet, area of a surface triangle.
#include <hooke/mesh/mesh.hpp>

namespace hooke::mesh {

/// Signed area of the planar triangle (a, b, c), m^2; positive when counter-clockwise.
double signed_area(const Vec2& a, const Vec2& b, const Vec2& c);
/// Signed volume of the tet (a, b, c, d), m^3; positive when (b-a, c-a, d-a) is right-handed.
double signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
/// Signed measure of element `e`: area (m^2) in 2D and for surface triangles (always >= 0 there),
/// volume (m^3) for tets. A quad's area is the shoelace sum over its cyclic nodes.
double element_measure(const Mesh& mesh, int e);
/// Sum of element_measure over every element: the area (m^2) of a 2D or surface mesh, the volume (m^3) of a tet mesh.
double total_measure(const Mesh& mesh);
/// Length of the bounding-box diagonal, m; the scale for relative tolerances.
double bounding_box_diagonal(const Mesh& mesh);

}  // namespace hooke::mesh
