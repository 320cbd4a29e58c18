#pragma once
/// Cleaning a triangle surface that came out of a segmentation (marching cubes on a label image) or a scan before it
/// is checked and tetrahedralized (docs/images.md): coincident nodes welded, degenerate and doubled triangles
/// removed, specks (separate pieces far smaller than the body) dropped, and the voxel steps smoothed away.
#include <hooke/mesh/mesh.hpp>

namespace hooke::mesh {

/// Nodes at exactly the same position merged into one (the first), triangles that then repeat a node removed, and
/// pairs of triangles on the same three nodes (a sheet of no thickness) removed; unused nodes dropped.
/// @pre kind kSurfaceTriangle. @return how many nodes were merged (via `merged`, when not null)
Mesh weld_surface(const Mesh& surface, int* merged = nullptr);

/// What drop_small_pieces removed.
struct PiecesReport {
  int pieces = 0;               ///< connected pieces (through shared edges) found
  int dropped = 0;              ///< pieces removed
  double dropped_volume = 0.0;  ///< the |volume| they enclosed together, m^3
  double kept_volume = 0.0;     ///< the |volume| of the pieces kept, m^3
};

/// Removes every connected piece whose enclosed |volume| is below `fraction` times the largest piece's (a speck
/// of a segmentation: a few voxels beside the organ). `fraction` in [0, 1]; 0 keeps every piece.
/// @pre kind kSurfaceTriangle
Mesh drop_small_pieces(const Mesh& surface, double fraction, PiecesReport* report = nullptr);

/// What close_small_holes did.
struct HolesReport {
  int closed = 0;           ///< holes (boundary loops) closed
  int left = 0;             ///< boundary loops longer than the limit, left open
  double added_area = 0.0;  ///< area of the triangles added, m^2
  int largest_closed = 0;   ///< edges of the longest loop closed
};

/// Closes every hole (a loop of boundary edges: edges of one triangle only) of at most `max_edges` edges with a fan of
/// triangles from a new node at the loop's centroid, oriented like the triangles around it. Longer loops (a face
/// scan's open back) and boundaries that are not simple loops are left as they are (the closed-surface check then
/// refuses them, naming an edge). @pre kind kSurfaceTriangle, max_edges >= 3
Mesh close_small_holes(const Mesh& surface, int max_edges, HolesReport* report = nullptr);

/// Taubin's lambda|mu smoothing (Taubin 1995, "A signal processing approach to fair surface design", SIGGRAPH):
/// `iterations` pairs of Laplacian steps (umbrella operator, uniform weights) with factors lambda = 0.5 and
/// mu = -0.53, which remove a voxel grid's steps without the shrinkage of plain Laplacian smoothing. In place.
/// @pre kind kSurfaceTriangle, iterations >= 0
void taubin_smooth(Mesh& surface, int iterations);

}  // namespace hooke::mesh
