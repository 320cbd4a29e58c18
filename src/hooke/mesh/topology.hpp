#pragma once
/// Derived connectivity: unique edges and boundary facets.
#include <array>
#include <hooke/mesh/mesh.hpp>
#include <vector>

namespace hooke::mesh {

/// Every edge of the mesh once, as (i, j) with i < j, sorted. For quads: the four sides only.
std::vector<std::array<int, 2>> unique_edges(const Mesh& mesh);

/// Boundary facets: for 2D meshes the edges that belong to one element, ordered as in that element
/// (so the outward normal of a counter-clockwise element's edge (a, b) is (b - a) rotated by -90 deg);
/// for tets the faces that belong to one tet, ordered so that their normal points out of it.
/// @return #F x 2 (2D) or #F x 3 (tet) node indices
/// @throws InvalidArgument for surface meshes (they have no boundary facets in this sense)
RowMatXi boundary_facets(const Mesh& mesh);

/// For each facet of `facets` (#F x 2 or #F x 3), its length (m) or area (m^2).
VecX facet_measures(const Mesh& mesh, const RowMatXi& facets);

}  // namespace hooke::mesh
