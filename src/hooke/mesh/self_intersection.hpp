#pragma once
/// Whether a triangle surface crosses itself: a scan whose surface passes through itself bounds no solid, and a
/// mesher fails on it far from the cause. Found with a uniform grid over the triangles' bounding boxes and an exact
/// sign test per candidate pair, so O(#T) for surfaces of even triangle size.
#include <array>
#include <hooke/mesh/mesh.hpp>
#include <vector>

namespace hooke::mesh {

/// Pairs (s, t), s < t, of triangles of the surface `mesh` (kind kSurfaceTriangle) that cross each other, sorted,
/// at most `max_pairs` of them. Two triangles cross when an edge of one passes through the interior of the other
/// (the orientation signs of its end points against the other's plane differ, and it passes inside the other's
/// three edges); signs within 1e-12 of the bounding box's scale count as zero, so touching is not crossing.
/// Triangles sharing an edge are not tested; triangles sharing one node are tested through their edges that do not
/// touch that node. Coplanar overlaps (a fold of zero angle) are not found.
/// @pre mesh.kind == kSurfaceTriangle
std::vector<std::array<int, 2>> self_intersections(const Mesh& mesh, int max_pairs = 16);

/// @throws InvalidMesh naming the first pair of crossing triangles (and mesh.source) and how many were found
void require_no_self_intersection(const Mesh& mesh);

}  // namespace hooke::mesh
