#pragma once
/// From a closed triangle surface (a scan's STL/OFF) to a tet mesh of the solid it bounds: the surface checks
/// before, Netgen's mesher (nglib, LGPL-2.1, linked dynamically, so hooke stays MIT), the quality and fidelity
/// report after (docs/meshing.md).
#include <functional>
#include <hooke/mesh/mesh.hpp>
#include <hooke/mesh/tet_quality.hpp>
#include <string>
#include <string_view>

namespace hooke::mesh {

/// What happens to the input surface.
enum class SurfaceMeshing {
  kKeep,    ///< the input triangles are the boundary of the tet mesh: nodes and enclosed volume preserved exactly,
            ///< the element count and shape near the surface follow the scan's triangles (the default: it meshes
            ///< every closed, non-crossing scan tried, docs/meshing.md)
  kRemesh,  ///< Netgen remeshes the surface at the target size first (its STL mesher: feature edges, curvature):
            ///< fewer elements; the nodes move onto a new surface, the Hausdorff distance says how far, and convex
            ///< parts lose volume as the chords' sag (size^2 / 8 R); it fails on some scans (boundary overlap)
};
/// "remesh" or "keep". @throws InvalidArgument naming the valid values
SurfaceMeshing surface_meshing_from_name(std::string_view name);
std::string_view surface_meshing_name(SurfaceMeshing meshing);

/// Which program fills the surface with tets.
enum class Mesher {
  kNetgen,  ///< Netgen's nglib, linked (LGPL-2.1), in process: the default, always installed
  kTetgen,  ///< TetGen's `tetgen` program run on files in a temporary folder (AGPL-3: never linked; `scripts/setup.sh`
            ///< installs it): about 8 times faster on large scans, keeps the surface only (io/mesher.hpp)
};
/// "netgen" or "tetgen". @throws InvalidArgument naming the valid values
Mesher mesher_from_name(std::string_view name);
std::string_view mesher_name(Mesher mesher);

struct TetrahedralizeOptions {
  Mesher mesher = Mesher::kNetgen;
  /// Largest tet edge, m; 0: the bounding-box diagonal / 25. (--max-volume V is the edge of the regular tet of
  /// volume V: (6 sqrt(2) V)^(1/3).) Inside the body; at a kept surface the scan's triangles set the size.
  double max_size = 0.0;
  SurfaceMeshing surface = SurfaceMeshing::kKeep;
  double fineness = 0.5;  ///< Netgen: 0 (coarse) .. 1 (fine): refinement at curvature and small features
  double grading = 0.3;   ///< Netgen: 0 (uniform) .. 1 (aggressive grading from small to large elements)
  /// Netgen: volume mesh optimisation passes, default 1. Measured by bench_tetrahedralize.cpp (medians of 3; the
  /// hardware is in docs/meshing.md): Stanford bunny (37 706 surface nodes) 0 passes 24 s with 1 003 slivers, 1
  /// pass 35.6 s (345 027 tets, radius ratio min 0.048, no sliver), 3 passes 56.3 s (322 581 tets, min 0.18, no
  /// sliver); CGAL's femur 4.8 s / 6.0 s at 1 / 3 passes with 33 / 32 slivers on its thin scan triangles either way
  int optimisation_steps = 1;
  /// Quality floor: a tet with radius_ratio below it fails the meshing, naming it; 0 (the default) reports only.
  /// Off by default because a kept scan bounds the quality of the tets on its thin triangles, and Netgen leaves a
  /// few interior slivers that its optimisation does not remove (CGAL's femur: 33 of 60 809 tets below 0.01, the
  /// worst 0.0002 on a scan triangle of quality 0.012); the model built on the mesh is then checked by what it does
  /// (certificate, inversion guard), docs/meshing.md.
  double min_radius_ratio = 0.0;
  double max_volume_error = 0.01;  ///< |V_tets / V_surface - 1| above this fails the meshing
  /// Separate pieces of the surface enclosing less than this fraction of the largest one's volume (specks of a
  /// segmentation beside the organ) are dropped with a warning naming their count and volume (mesh::drop_small_pieces),
  /// in [0, 1]; 0 keeps them (and a surface of several pieces is refused). Default 1e-3.
  double speck_fraction = 1e-3;
  /// Close holes of at most this many edges first (mesh::close_small_holes: a fan from the loop's centroid, the added
  /// area reported); 0 (the default, `--repair` off) refuses a surface with a hole, naming an edge
  int repair_max_edges = 0;
};

/// TetGen's quality targets (its -q switch), used by Mesher::kTetgen: radius-edge ratio and smallest dihedral angle.
inline constexpr double kTetgenRadiusEdge = 1.414;
inline constexpr double kTetgenMinDihedralDegrees = 10.0;

/// Below this radius ratio a tet is called a sliver in reports and warnings.
inline constexpr double kSliverRadiusRatio = 0.01;

/// What the meshing did and how good the result is.
struct TetrahedralizeReport {
  std::string backend;            ///< the mesher and its version, "netgen 6.2 (nglib)"
  TetrahedralizeOptions options;  ///< as used (max_size resolved, m)
  int surface_nodes = 0;          ///< input surface
  int surface_triangles = 0;
  int flipped_triangles = 0;    ///< input triangles reoriented by check_closed_surface
  int closed_holes = 0;         ///< holes closed (options.repair_max_edges)
  double added_area = 0.0;      ///< their triangles' area, m^2
  int dropped_pieces = 0;       ///< specks dropped (options.speck_fraction)
  double dropped_volume = 0.0;  ///< the volume they enclosed, m^3
  double surface_volume = 0.0;  ///< enclosed by the input surface, m^3
  int nodes = 0;                ///< output tet mesh
  int tets = 0;
  double volume = 0.0;              ///< of the tets, m^3
  double volume_error = 0.0;        ///< volume / surface_volume - 1
  bool surface_preserved = false;   ///< the input nodes are the first surface_nodes nodes, unmoved
  double hausdorff = 0.0;           ///< node_hausdorff_distance of the input and output surfaces, m
  double hausdorff_relative = 0.0;  ///< hausdorff / the bounding-box diagonal
  TetQualityReport quality;
  int slivers = 0;       ///< tets with radius ratio below kSliverRadiusRatio (a warning names them)
  double seconds = 0.0;  ///< wall time of the meshing (checks and report included)
  /// One line for logs and model files: backend, options, counts, volume error, Hausdorff, quality, time.
  std::string summary() const;
};

/// The tet mesh of the solid bounded by `surface` (kind kSurfaceTriangle, m), validated, tets positively oriented.
/// Before meshing: specks dropped (options.speck_fraction, a warning), check_closed_surface (closed, manifold,
/// oriented, one piece) and require_no_self_intersection;
/// a warning when the surface is larger than 10 m across (a file in millimetres read as metres: give --unit mm).
/// After: the volume within options.max_volume_error of the enclosed volume, every tet's radius ratio above
/// options.min_radius_ratio, the quality and Hausdorff distance in `report`. Netgen's own messages are silenced;
/// calls are serialised (Netgen keeps global state). options.mesher must be kNetgen here: TetGen runs as a program
/// on files, which io::tetrahedralize (io/mesher.hpp) does.
/// @throws InvalidMesh naming the element of the input surface that fails a check, or the mesher's failure and
///   its message, or the tet below the quality floor or the volume off by more than allowed, with what to change;
///   InvalidArgument for options out of range
Mesh tetrahedralize(Mesh surface, const TetrahedralizeOptions& options = {}, TetrahedralizeReport* report = nullptr);

/// A volume mesher: `fill` returns tets (positively oriented) filling a surface that has passed the checks of
/// tetrahedralize, with the options as resolved there (max_size > 0).
struct VolumeMesher {
  std::string name;  ///< the mesher and its version, as reports give it
  std::function<Mesh(const Mesh& surface, const TetrahedralizeOptions& options)> fill;
};
/// Netgen's nglib in process (what the three-argument tetrahedralize uses).
VolumeMesher netgen_mesher();
/// tetrahedralize with the given mesher in place of the one options.mesher names: the same checks before and
/// report after. io::tetrahedralize supplies TetGen's (a program run on files, which this layer cannot do).
Mesh tetrahedralize(Mesh surface, const TetrahedralizeOptions& options, TetrahedralizeReport* report,
                    const VolumeMesher& mesher);

/// The edge length (m) of the regular tet of volume `volume` (m^3): what --max-volume sets max_size to.
/// @pre volume > 0
double edge_of_regular_tet(double volume);

/// The volume (m^3) of the regular tet of edge `edge` (m), edge^3 / (6 sqrt(2)): the inverse of
/// edge_of_regular_tet, TetGen's volume bound (-a) for a largest edge. @pre edge > 0
double regular_tet_volume(double edge);

/// Sets options.max_size from the largest tet edge `max_edge` (m) or the largest tet volume `max_volume` (m^3),
/// whichever is not 0 (both 0: left as it is). @throws InvalidArgument when both are given or one is negative
void set_mesh_size(TetrahedralizeOptions& options, double max_edge, double max_volume);

}  // namespace hooke::mesh
