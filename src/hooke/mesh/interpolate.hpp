#pragma once
/// Point location and interpolation of nodal fields with the elements' own shape functions: linear on
/// triangles and tets (barycentric), bilinear on quads (isoparametric map inverted by Newton's method).
#include <hooke/mesh/mesh.hpp>

namespace hooke::mesh {

/// Values of the nodal field `values` (#V x c, any unit) at `points` (#P x dim, m), each interpolated in an
/// element that contains the point (within 1e-9 of the bounding-box diagonal; on shared faces any of them).
/// Brute force over the elements: O(#P x #E), meant for meshes of a few thousand elements.
/// @pre mesh is a valid triangle, quad or tet mesh; values.rows() == #V; points.cols() == mesh.dim()
/// @throws InvalidArgument naming the first point that lies in no element
RowMatX interpolate_nodal(const Mesh& mesh, const RowMatX& values, const RowMatX& points);

}  // namespace hooke::mesh
