#pragma once
/// The condition of Arnab & Raja's radial construction: the surface is star-shaped with respect to the object
/// centre (the paper assumes "the initial shape of object is convex with known centre of object").
#include <hooke/mesh/mesh.hpp>

namespace hooke::surface {

/// Checks that the radial construction of Arnab & Raja (Fig. 5) is possible from `centre` (m): every triangle
/// faces away from it (the tet (centre, a, b, c) has positive volume, so no radial link crosses the surface),
/// and `centre` lies behind every node's tangent plane ((p_i - centre) . N_i > 0 with N_i the node normal).
/// @pre `mesh` is a closed, outward-oriented surface (mesh::check_closed_surface)
/// @throws InvalidMesh naming the first triangle or node that fails, with the centre used
void require_star_shaped(const mesh::Mesh& mesh, const Vec3& centre);

}  // namespace hooke::surface
