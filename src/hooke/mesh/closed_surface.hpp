#pragma once
/// Checks that a triangle surface bounds a solid: closed, manifold, consistently and outwards oriented, one piece,
/// and the volume it encloses. Both the tetrahedralization of a scan (mesh/tetrahedralize.hpp) and Arnab & Raja's
/// surface model (surface/) start from such a surface.
#include <hooke/mesh/mesh.hpp>

namespace hooke::mesh {

struct SurfaceCheckReport {
  int flipped_triangles = 0;  ///< triangles whose orientation was reversed to agree with their neighbours
  bool reversed_all = false;  ///< true when the whole surface was turned inside out (normals now point out)
  double volume = 0.0;        ///< enclosed volume, m^3 (> 0)
};

/// Makes `mesh` (kind kSurfaceTriangle) a closed, outward-oriented surface in place.
/// Each undirected edge must belong to exactly two triangles and each node's triangles must form one fan;
/// triangles are reoriented to agree with their neighbours (a warning names how many), and the whole surface is
/// reversed when it encloses a negative volume. Self-intersection is a separate check (mesh/self_intersection.hpp).
/// @throws InvalidMesh naming the edge, node or triangle (and mesh.source) for: a wrong element kind, an open
///   edge (a hole), an edge shared by three or more triangles, a node where two fans meet, a non-orientable
///   surface (Moebius-like), several disconnected pieces, or a zero enclosed volume.
SurfaceCheckReport check_closed_surface(Mesh& mesh);

/// Volume enclosed by the closed, outward-oriented surface with flat node positions x (m, node-major, 3 per
/// node), m^3: the sum of the signed tets (origin, a, b, c). Exact for any closed surface, also non-convex.
double enclosed_volume(const RowMatXi& triangles, const Eigen::Ref<const VecX>& x);

/// Centroid of the enclosed volume, m. @pre `mesh` is a closed, outward-oriented surface (check_closed_surface)
Vec3 volume_centroid(const Mesh& mesh);

}  // namespace hooke::mesh
