#pragma once
/// Where a body is held and where it is loaded: the one rule for supports, in its named variants. A support or a
/// loaded region is an end of one axis, the face itself (band kFace) or a band of the extent along the axis:
///   - the papers' clamped bottom face and loaded top face (Lloyd et al. 2007, Sec. 5): end_nodes / end_facets, kFace;
///   - a body with no flat top (a scanned organ or bone) held and loaded at its end bands, kEndBand;
///   - the self-weight fit's support, widened from the face to a slab until it holds the body rigidly;
///   - the identification's reference loads along every axis: the boundary facets that face an end, facing_end_facets.
#include <hooke/core/types.hpp>
#include <hooke/mesh/mesh.hpp>
#include <vector>

namespace hooke::model {

/// The low (minimum coordinate) or high end of an axis.
enum class End { kLow, kHigh };

/// Band width of the face itself: within 1e-6 of the bounding-box diagonal of the end.
inline constexpr double kFace = 0.0;
/// The fraction of the height held and loaded at each end of a body with no flat top (make_load_case).
inline constexpr double kEndBand = 0.05;

/// Distance from an end within which a node belongs to it, m: 1e-6 of the bounding-box diagonal for kFace, else
/// band x the mesh's extent along `axis`.
/// @pre 0 <= axis < mesh.dim(), band >= 0
double end_tolerance(const mesh::Mesh& mesh, int axis, double band);

/// Nodes within end_tolerance(mesh, axis, band) of the low or high end of `axis`, in increasing order.
std::vector<int> end_nodes(const mesh::Mesh& mesh, int axis, End end, double band);

/// Rows of `facets` (boundary facets, mesh::boundary_facets) whose nodes all lie within end_tolerance of the end.
std::vector<int> end_facets(const mesh::Mesh& mesh, const RowMatXi& facets, int axis, End end, double band);

/// Boundary facets with their outward unit normals, centroids (m) and measures (m^2 in 3D, m in 2D).
struct BoundaryFacets {
  RowMatXi facets;
  RowMatX normals, centroids;
  VecX measures;
};

/// The boundary facets of a validated triangle, quad or tet mesh with their geometry (normals point outward, as
/// mesh::boundary_facets orders them).
BoundaryFacets boundary_facets_with_geometry(const mesh::Mesh& mesh);

/// Rows of b.facets that face an end of `axis`: outward normal within 60 degrees of the axis pointing out of that
/// end (-axis for kLow) and centroid within `band` x the extent of it.
/// @pre 0 < band <= 1
std::vector<int> facing_end_facets(const mesh::Mesh& mesh, const BoundaryFacets& b, int axis, End end, double band);

}  // namespace hooke::model
