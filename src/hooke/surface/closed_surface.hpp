#pragma once
/// Checks that a triangle surface can carry Arnab & Raja's surface model: closed, manifold, consistently and
/// outwards oriented, one piece, and star-shaped with respect to the object centre (the paper assumes "the
/// initial shape of object is convex with known centre of object").
#include <hooke/mesh/mesh.hpp>

namespace hooke::surface {

struct SurfaceCheckReport {
  int flipped_triangles = 0;  ///< triangles whose orientation was reversed to agree with their neighbours
  bool reversed_all = false;  ///< true when the whole surface was turned inside out (normals now point out)
  double volume = 0.0;        ///< enclosed volume, m^3 (> 0)
};

/// Makes `mesh` (kind kSurfaceTriangle) a closed, outward-oriented surface in place.
/// Each undirected edge must belong to exactly two triangles and each node's triangles must form one fan;
/// triangles are reoriented to agree with their neighbours (a warning names how many), and the whole surface is
/// reversed when it encloses a negative volume.
/// @throws InvalidMesh naming the edge, node or triangle (and mesh.source) for: a wrong element kind, an open
///   edge (a hole), an edge shared by three or more triangles, a node where two fans meet, a non-orientable
///   surface (Moebius-like), several disconnected pieces, or a zero enclosed volume.
SurfaceCheckReport check_closed_surface(mesh::Mesh& mesh);

/// Volume enclosed by the closed, outward-oriented surface with flat node positions x (m, node-major, 3 per
/// node), m^3: the sum of the signed tets (origin, a, b, c). Exact for any closed surface, also non-convex.
double enclosed_volume(const RowMatXi& triangles, const Eigen::Ref<const VecX>& x);

/// Centroid of the enclosed volume, m. @pre `mesh` is a closed, outward-oriented surface (check_closed_surface)
Vec3 volume_centroid(const mesh::Mesh& mesh);

/// Checks that the radial construction of Arnab & Raja (Fig. 5) is possible from `centre` (m): every triangle
/// faces away from it (the tet (centre, a, b, c) has positive volume, so no radial link crosses the surface),
/// and `centre` lies behind every node's tangent plane ((p_i - centre) . N_i > 0 with N_i the node normal).
/// @throws InvalidMesh naming the first triangle or node that fails, with the centre used
void require_star_shaped(const mesh::Mesh& mesh, const Vec3& centre);

}  // namespace hooke::surface
