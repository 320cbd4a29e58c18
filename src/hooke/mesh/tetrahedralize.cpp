#include <chrono>
#include <cmath>
#include <cstdio>
#include <hooke/core/error.hpp>
#include <hooke/core/log.hpp>
#include <hooke/core/name_table.hpp>
#include <hooke/mesh/closed_surface.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/mesh/self_intersection.hpp>
#include <hooke/mesh/surface_cleanup.hpp>
#include <hooke/mesh/surface_distance.hpp>
#include <hooke/mesh/tetrahedralize.hpp>
#include <hooke/mesh/topology.hpp>
#include <hooke/mesh/validate.hpp>
#include <iostream>
#include <mutex>
#include <ostream>
#include <string>
#include <utility>

// Netgen's C interface (Debian libnglib-dev): its declarations live in namespace nglib in the library.
namespace nglib {
#include <nglib.h>
}
#undef DLL_HEADER
// Netgen's message switches and streams (libmesh, libngcore): hooke's library never prints (core/log.hpp), so
// they are turned off and pointed at a stream that discards.
namespace netgen {
extern int printmessage_importance, printwarnings, printerrors, printdots;
extern std::ostream* mycout;
}  // namespace netgen
namespace ngcore {
extern std::ostream* testout;
}

namespace hooke::mesh {
namespace {

std::string surface_name(const Mesh& m) { return m.source.empty() ? std::string("the surface") : m.source; }

std::string fixed(double v, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
  return buffer;
}

std::string general(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.4g", v);
  return buffer;
}

// Holes closed (--repair) and specks dropped (--speck-fraction) before the checks, each with a warning.
void repair(Mesh& surface, const TetrahedralizeOptions& o, TetrahedralizeReport& r) {
  HolesReport holes;
  PiecesReport pieces;
  if (o.repair_max_edges > 0) surface = close_small_holes(surface, o.repair_max_edges, &holes);
  if (o.speck_fraction > 0.0) surface = drop_small_pieces(surface, o.speck_fraction, &pieces);
  r.closed_holes = holes.closed;
  r.added_area = holes.added_area;
  r.dropped_pieces = pieces.dropped;
  r.dropped_volume = pieces.dropped_volume;
  const std::string name = surface_name(surface);
  if (holes.closed > 0)
    log_warning(name + ": closed " + std::to_string(holes.closed) + " hole(s) of up to " +
                std::to_string(holes.largest_closed) + " edges, adding " + general(holes.added_area) + " m^2");
  if (pieces.dropped > 0)
    log_warning(name + ": dropped " + std::to_string(pieces.dropped) + " separate piece(s) of " +
                general(pieces.dropped_volume) + " m^3 together, below " + general(o.speck_fraction) +
                " of the largest piece's volume (--speck-fraction 0 keeps them)");
}

void check_options(const TetrahedralizeOptions& o) {
  if (!(o.max_size >= 0.0) || !std::isfinite(o.max_size))
    throw InvalidArgument("the mesh size must be a length > 0 m (or 0 for automatic), not " + general(o.max_size));
  if (!(o.fineness >= 0.0 && o.fineness <= 1.0))
    throw InvalidArgument("the fineness must lie in [0, 1], not " + general(o.fineness));
  if (!(o.grading >= 0.0 && o.grading <= 1.0))
    throw InvalidArgument("the grading must lie in [0, 1], not " + general(o.grading));
  if (o.optimisation_steps < 0 || o.optimisation_steps > 100)
    throw InvalidArgument("the optimisation steps must lie in [0, 100], not " + std::to_string(o.optimisation_steps));
  if (!(o.min_radius_ratio >= 0.0 && o.min_radius_ratio < 1.0))
    throw InvalidArgument("the quality floor (radius ratio) must lie in [0, 1), not " + general(o.min_radius_ratio));
  if (!(o.max_volume_error > 0.0) || !std::isfinite(o.max_volume_error))
    throw InvalidArgument("the allowed volume error must be > 0, not " + general(o.max_volume_error));
  if (o.repair_max_edges < 0 || o.repair_max_edges == 1 || o.repair_max_edges == 2)
    throw InvalidArgument("holes to repair have at least 3 edges, not " + std::to_string(o.repair_max_edges));
  if (!(o.speck_fraction >= 0.0 && o.speck_fraction <= 1.0))
    throw InvalidArgument("the speck fraction must lie in [0, 1], not " + general(o.speck_fraction));
  if (o.mesher == Mesher::kTetgen && o.surface == SurfaceMeshing::kRemesh)
    throw InvalidArgument("the tetgen mesher keeps the scan's triangles; --surface-mesh remesh is Netgen's");
}

// Owns one Netgen mesh; every call into Netgen goes through run(), which turns its exceptions into InvalidMesh.
class NetgenSession {
 public:
  NetgenSession() {
    static std::once_flag once;
    std::call_once(once, [] { nglib::Ng_Init(); });
    static std::ostream discard(nullptr);
    netgen::printmessage_importance = 0;
    netgen::printwarnings = 0;
    netgen::printerrors = 0;
    netgen::printdots = 0;
    netgen::mycout = &discard;
    ngcore::testout = &discard;
    m_mesh = nglib::Ng_NewMesh();
    // Netgen's optimiser also writes to std::cerr directly ("BFGS update error2"): discarded while it runs.
    m_cerr = std::cerr.rdbuf(nullptr);
  }
  ~NetgenSession() {
    nglib::Ng_DeleteMesh(m_mesh);
    std::cerr.rdbuf(m_cerr);
    std::cerr.clear();
  }
  NetgenSession(const NetgenSession&) = delete;
  NetgenSession& operator=(const NetgenSession&) = delete;
  nglib::Ng_Mesh* mesh() { return m_mesh; }

 private:
  nglib::Ng_Mesh* m_mesh;
  std::streambuf* m_cerr;
};

std::mutex& netgen_mutex() {
  static std::mutex m;
  return m;
}

void require_ok(nglib::Ng_Result result, const char* stage, const Mesh& surface) {
  if (result == nglib::NG_OK) return;
  throw InvalidMesh("Netgen could not " + std::string(stage) + " of " + surface_name(surface) + " (result " +
                    std::to_string(static_cast<int>(result)) +
                    "); try --surface keep, a smaller --size, or repair the surface");
}

// The tets Netgen made, as a hooke mesh (positively oriented: Netgen's tets have the opposite orientation).
Mesh netgen_volume(const Mesh& surface, const TetrahedralizeOptions& o) {
  std::lock_guard<std::mutex> lock(netgen_mutex());
  NetgenSession session;
  nglib::Ng_Meshing_Parameters mp;
  mp.maxh = o.max_size;
  mp.fineness = o.fineness;
  mp.grading = o.grading;
  mp.optsteps_3d = o.optimisation_steps;
  mp.optsteps_2d = o.optimisation_steps;
  try {
    if (o.surface == SurfaceMeshing::kKeep) {
      for (int i = 0; i < surface.node_count(); ++i) {
        double p[3] = {surface.nodes(i, 0), surface.nodes(i, 1), surface.nodes(i, 2)};
        nglib::Ng_AddPoint(session.mesh(), p);
      }
      for (int t = 0; t < surface.element_count(); ++t) {
        int pi[3] = {surface.elements(t, 0) + 1, surface.elements(t, 1) + 1, surface.elements(t, 2) + 1};
        nglib::Ng_AddSurfaceElement(session.mesh(), nglib::NG_TRIG, pi);
      }
    } else {
      // The STL geometry is Netgen's (nglib offers no way to free it): a few bytes per input triangle per call.
      nglib::Ng_STL_Geometry* geometry = nglib::Ng_STL_NewGeometry();
      for (int t = 0; t < surface.element_count(); ++t) {
        double p[3][3];
        for (int k = 0; k < 3; ++k)
          for (int c = 0; c < 3; ++c) p[k][c] = surface.nodes(surface.elements(t, k), c);
        nglib::Ng_STL_AddTriangle(geometry, p[0], p[1], p[2]);
      }
      require_ok(nglib::Ng_STL_InitSTLGeometry(geometry), "read the triangles", surface);
      require_ok(nglib::Ng_STL_MakeEdges(geometry, session.mesh(), &mp), "find the feature edges", surface);
      require_ok(nglib::Ng_STL_GenerateSurfaceMesh(geometry, session.mesh(), &mp), "remesh the surface", surface);
    }
    require_ok(nglib::Ng_GenerateVolumeMesh(session.mesh(), &mp), "fill the volume", surface);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw InvalidMesh("Netgen could not mesh " + surface_name(surface) + ": " + e.what() +
                      (o.surface == SurfaceMeshing::kKeep
                           ? "; try --surface remesh, or repair the surface"
                           : "; try --surface keep, another --size, or repair the surface"));
  }
  const int np = nglib::Ng_GetNP(session.mesh()), ne = nglib::Ng_GetNE(session.mesh());
  if (ne == 0) throw InvalidMesh("Netgen made no tets of " + surface_name(surface) + "; try a smaller --size");
  RowMatX nodes(np, 3);
  for (int i = 0; i < np; ++i) {
    double p[3];
    nglib::Ng_GetPoint(session.mesh(), i + 1, p);
    nodes.row(i) << p[0], p[1], p[2];
  }
  RowMatXi tets(ne, 4);
  for (int e = 0; e < ne; ++e) {
    int pi[10];
    if (nglib::Ng_GetVolumeElement(session.mesh(), e + 1, pi) != nglib::NG_TET)
      throw InvalidMesh("Netgen made an element other than a tet in " + surface_name(surface));
    tets.row(e) << pi[0] - 1, pi[2] - 1, pi[1] - 1, pi[3] - 1;
  }
  return make_mesh(ElementKind::kTet, std::move(nodes), std::move(tets), surface.source);
}

}  // namespace

constexpr NameTable<Mesher, 2> kMeshers{"mesher", {{{Mesher::kNetgen, "netgen"}, {Mesher::kTetgen, "tetgen"}}}};

Mesher mesher_from_name(std::string_view name) { return kMeshers.from_name(name); }
std::string_view mesher_name(Mesher mesher) { return kMeshers.name(mesher); }

constexpr NameTable<SurfaceMeshing, 2> kSurfaceMeshings{
    "surface meshing", {{{SurfaceMeshing::kRemesh, "remesh"}, {SurfaceMeshing::kKeep, "keep"}}}};

SurfaceMeshing surface_meshing_from_name(std::string_view name) { return kSurfaceMeshings.from_name(name); }
std::string_view surface_meshing_name(SurfaceMeshing meshing) { return kSurfaceMeshings.name(meshing); }

double edge_of_regular_tet(double volume) {
  if (!(volume > 0.0) || !std::isfinite(volume))
    throw InvalidArgument("the largest tet volume must be > 0 m^3, not " + general(volume));
  return std::cbrt(6.0 * std::sqrt(2.0) * volume);
}

double regular_tet_volume(double edge) { return edge * edge * edge / (6.0 * std::sqrt(2.0)); }

void set_mesh_size(TetrahedralizeOptions& options, double max_edge, double max_volume) {
  if (max_edge != 0.0 && max_volume != 0.0) throw InvalidArgument("give a largest tet edge or volume, not both");
  if (max_edge < 0.0 || !std::isfinite(max_edge))
    throw InvalidArgument("the largest tet edge must be a length > 0 m, not " + general(max_edge));
  if (max_edge > 0.0) options.max_size = max_edge;
  if (max_volume != 0.0) options.max_size = edge_of_regular_tet(max_volume);
}

std::string TetrahedralizeReport::summary() const {
  const std::string netgen_only = options.mesher == Mesher::kNetgen ? ", fineness " + general(options.fineness) +
                                                                          ", grading " + general(options.grading)
                                                                    : std::string();
  return backend + ", surface " + std::string(surface_meshing_name(options.surface)) + ", size " +
         general(options.max_size) + " m" + netgen_only + ": " + std::to_string(surface_nodes) + " surface nodes, " +
         std::to_string(surface_triangles) + " triangles" +
         (dropped_pieces > 0 ? " (" + std::to_string(dropped_pieces) + " specks dropped)" : std::string()) +
         (closed_holes > 0
              ? " (" + std::to_string(closed_holes) + " holes closed, " + general(added_area) + " m^2 added)"
              : std::string()) +
         " -> " + std::to_string(nodes) + " nodes, " + std::to_string(tets) + " tets; volume " +
         (volume_error >= 0.0 ? "+" : "") + fixed(100.0 * volume_error, 2) + " % of the enclosed volume; Hausdorff " +
         general(hausdorff) + " m (" + fixed(100.0 * hausdorff_relative, 2) + " % of the diagonal" +
         (surface_preserved ? ", surface nodes preserved" : "") + "); radius ratio min " +
         fixed(quality.min_radius_ratio, 3) + " mean " + fixed(quality.mean_radius_ratio, 3) + ", dihedral " +
         fixed(quality.min_dihedral, 1) + " .. " + fixed(quality.max_dihedral, 1) + " deg, " + std::to_string(slivers) +
         " slivers; " + fixed(seconds, 2) + " s";
}

VolumeMesher netgen_mesher() { return {"netgen 6.2 (nglib)", netgen_volume}; }

Mesh tetrahedralize(Mesh surface, const TetrahedralizeOptions& options, TetrahedralizeReport* report) {
  if (options.mesher != Mesher::kNetgen)
    throw InvalidArgument("the " + std::string(mesher_name(options.mesher)) +
                          " mesher runs a program on files: io::tetrahedralize (io/mesher.hpp) does that");
  return tetrahedralize(std::move(surface), options, report, netgen_mesher());
}

Mesh tetrahedralize(Mesh surface, const TetrahedralizeOptions& options, TetrahedralizeReport* report,
                    const VolumeMesher& mesher) {
  const auto start = std::chrono::steady_clock::now();
  check_options(options);
  if (surface.kind != ElementKind::kSurfaceTriangle)
    throw InvalidMesh("tetrahedralizing needs a closed triangle surface; " + surface_name(surface) + " holds " +
                      std::string(element_kind_name(surface.kind)) + " elements");
  TetrahedralizeReport r;
  r.backend = mesher.name;
  r.options = options;
  repair(surface, options, r);
  r.surface_nodes = surface.node_count();
  r.surface_triangles = surface.element_count();
  const SurfaceCheckReport check = check_closed_surface(surface);
  r.flipped_triangles = check.flipped_triangles;
  r.surface_volume = check.volume;
  require_no_self_intersection(surface);
  const double diagonal = bounding_box_diagonal(surface);
  if (diagonal > 10.0)
    log_warning(surface_name(surface) + " is " + general(diagonal) +
                " m across: if its coordinates are millimetres, give --unit mm (hooke works in metres)");
  if (r.options.max_size == 0.0) r.options.max_size = diagonal / 25.0;

  Mesh tets = mesher.fill(surface, r.options);
  validate(tets);
  r.nodes = tets.node_count();
  r.tets = tets.element_count();
  r.volume = total_measure(tets);
  r.volume_error = r.volume / r.surface_volume - 1.0;
  r.surface_preserved =
      tets.node_count() >= surface.node_count() && tets.nodes.topRows(surface.node_count()) == surface.nodes;
  const RowMatXi boundary = boundary_facets(tets);
  r.hausdorff = node_hausdorff_distance(surface.nodes, surface.elements, tets.nodes, boundary);
  r.hausdorff_relative = r.hausdorff / diagonal;
  r.quality = tet_quality(tets, r.options.min_radius_ratio);
  r.slivers = tet_quality(tets, kSliverRadiusRatio).below_floor;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (report) *report = r;
  log(LogLevel::kInfo, "tetrahedralized " + surface_name(surface) + ": " + r.summary());
  if (r.slivers > 0 && r.options.min_radius_ratio == 0.0)
    log_warning(std::to_string(r.slivers) + " of the " + std::to_string(r.tets) + " tets of " + surface_name(surface) +
                " are slivers (radius ratio below " + fixed(kSliverRadiusRatio, 2) + ", worst " +
                fixed(r.quality.min_radius_ratio, 4) + " at tet " + std::to_string(r.quality.worst_element) +
                "); --quality Q refuses a mesh with tets below Q");
  if (std::abs(r.volume_error) > r.options.max_volume_error)
    throw InvalidMesh("the tets of " + surface_name(surface) + " enclose " + fixed(100.0 * r.volume_error, 2) +
                      " % more volume than the surface (allowed: " + fixed(100.0 * r.options.max_volume_error, 2) +
                      " %); give a smaller --size, or --surface keep");
  if (r.quality.below_floor > 0)
    throw InvalidMesh(std::to_string(r.quality.below_floor) + " tets of the mesh of " + surface_name(surface) +
                          " have a radius ratio below the quality floor " + fixed(r.options.min_radius_ratio, 3) +
                          " (worst: tet " + std::to_string(r.quality.worst_element) + ", " +
                          fixed(r.quality.min_radius_ratio, 4) +
                          "): slivers invert first under load; try --surface remesh, more optimisation steps, or "
                          "a lower --quality",
                      r.quality.worst_element);
  tets.source = surface.source.empty() ? "tetrahedralized surface" : surface.source + " (tetrahedralized)";
  return tets;
}

}  // namespace hooke::mesh
