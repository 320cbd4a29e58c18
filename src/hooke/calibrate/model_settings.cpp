#include <hooke/calibrate/model_settings.hpp>
#include <hooke/core/error.hpp>
#include <hooke/surface/anchor_block.hpp>
#include <hooke/surface/volume_penalty_block.hpp>

namespace hooke::calibrate {
namespace {

using settings::Setting;
using Options = ModelOptions;

// The commands that make a model; the viewer's live settings are marked settings::kView on top of them.
constexpr unsigned kModel = settings::kCalibrate | settings::kCompare | settings::kSimulate | settings::kBatch;
constexpr unsigned kLive = kModel | settings::kView;
constexpr unsigned kTets = kModel | settings::kMesh;

std::vector<std::string> names_of(std::initializer_list<const char*> names) { return {names.begin(), names.end()}; }

std::vector<Setting<Options>> rows() {
  std::vector<Setting<Options>> r;
  r.push_back(settings::choice<Options>(
      "method", kLive,
      "The model: auto (the method of smallest measured error for the element kind and nu), a calibration method "
      "(docs/methods/), surface (Arnab & Raja's surface model) or fem (the FEM model of the material's law)",
      model_method_names, [](Options& o, std::string_view t) { o.method = std::string(t); },
      [](const Options& o) { return o.method; }));
  Setting<Options> density =
      settings::number<Options>("density", "kg/m^3", 0.0, settings::kUnbounded, kLive, "Density for the lumped masses",
                                [](Options& o) -> double& { return o.density; });
  density.exclusive_min = true;
  r.push_back(density);
  r.push_back(settings::number<Options>(
      "spring-exponent", "", -8.0, 8.0, kLive | settings::kBench,
      "The springs' large-strain law: Seth-Hill exponent m of E = k l0^2 e_m(l/l0)^2 / 2 (1: Hookean springs)",
      [](Options& o) -> double& { return o.spring_exponent; }));
  r.push_back(settings::number<Options>(
      "volume-exponent", "", -8.0, 8.0, kLive | settings::kBench,
      "The volume terms' large-strain law: Seth-Hill exponent q of E = k_V e_q(V/V0)^2 / 2 (1: quadratic; <= 0 a "
      "barrier against flattening)",
      [](Options& o) -> double& { return o.volume_exponent; }));
  r.push_back(settings::choice<Options>(
      "scheme", kLive, "surface: Arnab & Raja's distribution scheme; it sets the anchor law and volume penalty",
      [] {
        return names_of({"A", "B", "C", "D"});
      },
      [](Options& o, std::string_view t) {
        o.surface.scheme = surface_scheme_from_name(t);
        o.surface.anchor_law.reset();  // the scheme's own anchor law and volume penalty
        o.surface.volume_penalty.reset();
      },
      [](const Options& o) { return std::string(surface_scheme_name(o.surface.scheme)); }));
  r.push_back(settings::choice<Options>(
      "anchor-law", kLive, "surface: the anchors' law instead of the scheme's",
      [] {
        return names_of({"single", "blend", "tensor"});
      },
      [](Options& o, std::string_view t) { o.surface.anchor_law = surface::anchor_law_from_name(t); },
      [](const Options& o) {
        return o.surface.anchor_law ? std::string(surface::anchor_law_name(*o.surface.anchor_law)) : std::string();
      }));
  r.push_back(settings::choice<Options>(
      "volume-force", kLive, "surface: the volume penalty's force (Eq. 3-4 as printed, per node, or the energy's)",
      [] {
        return names_of({"nodal", "printed", "energy"});
      },
      [](Options& o, std::string_view t) { o.surface.volume_force = surface::volume_force_from_name(t); },
      [](const Options& o) { return std::string(surface::volume_force_name(o.surface.volume_force)); }));
  Setting<Options> centre = settings::row<Options>(
      "centre", settings::Type::kText, "m", "surface: the object centre x,y,z (default: the volume centroid)", kModel);
  centre.set = [](Options& o, std::string_view t) {
    double c[3];
    size_t start = 0;
    for (int k = 0; k < 3; ++k) {
      const size_t end = k < 2 ? t.find(',', start) : t.size();
      if (end == std::string_view::npos || (k == 2 && t.find(',', start) != std::string_view::npos))
        throw InvalidArgument("centre needs three components x,y,z (m), not '" + std::string(t) + "'");
      c[k] = settings::parse_number("centre", t.substr(start, end - start));
      start = end + 1;
    }
    o.surface.centre = Vec3(c[0], c[1], c[2]);
  };
  centre.get = [](const Options& o) {
    if (!o.surface.centre) return std::string();
    const Vec3& c = *o.surface.centre;
    return settings::number_text(c.x()) + "," + settings::number_text(c.y()) + "," + settings::number_text(c.z());
  };
  r.push_back(centre);
  // A closed surface made into tets (mesh::tetrahedralize).
  r.push_back(settings::choice<Options>(
      "mesher", kTets,
      "Closed surface to tets: netgen (linked) or tetgen (TetGen's program on files, about 8x faster on large scans, "
      "keeps the surface; Debian's tetgen program, never linked)",
      [] {
        return names_of({"netgen", "tetgen"});
      },
      [](Options& o, std::string_view t) { o.tetrahedralize.mesher = mesh::mesher_from_name(t); },
      [](const Options& o) { return std::string(mesh::mesher_name(o.tetrahedralize.mesher)); }));
  Setting<Options> size = settings::number<Options>(
      "size", "m", 0.0, settings::kUnbounded, kTets,
      "Closed surface to tets: the largest tet edge inside the body (0: the bounding-box diagonal / 25)",
      [](Options& o) -> double& { return o.tetrahedralize.max_size; });
  size.length_power = 1;
  r.push_back(size);
  Setting<Options> volume = settings::row<Options>(
      "max-volume", settings::Type::kNumber, "m^3",
      "Closed surface to tets: the largest tet volume, instead of size (the edge of the regular tet of that volume; 0: "
      "not given)",
      kTets, 0.0, settings::kUnbounded);
  volume.length_power = 3;
  volume.set = [](Options& o, std::string_view t) {
    if (o.tetrahedralize.max_size > 0.0) throw InvalidArgument("give size or max-volume, not both");
    mesh::set_mesh_size(o.tetrahedralize, 0.0, settings::parse_number("max-volume", t));
  };
  volume.get = [](const Options&) { return std::string("0"); };
  r.push_back(volume);
  r.push_back(settings::number<Options>(
      "quality", "", 0.0, 1.0, kTets,
      "Closed surface to tets: refuse the mesh if a tet's radius ratio (1 regular, 0 flat) is below this; 0 reports",
      [](Options& o) -> double& { return o.tetrahedralize.min_radius_ratio; }));
  r.push_back(settings::choice<Options>(
      "surface-mesh", kTets,
      "Closed surface to tets: keep (the scan's triangles bound the tets: nodes and volume exact) or remesh (Netgen "
      "remeshes the surface at size first)",
      [] {
        return names_of({"keep", "remesh"});
      },
      [](Options& o, std::string_view t) { o.tetrahedralize.surface = mesh::surface_meshing_from_name(t); },
      [](const Options& o) { return std::string(mesh::surface_meshing_name(o.tetrahedralize.surface)); }));
  r.push_back(settings::integer<Options>(
      "repair", 0, 100000, kTets,
      "Closed surface to tets: close holes of at most this many edges with a fan of triangles (the added area is "
      "reported); 0 refuses a surface with a hole",
      [](Options& o) -> int& { return o.tetrahedralize.repair_max_edges; }));
  r.push_back(settings::number<Options>(
      "speck-fraction", "", 0.0, 1.0, kTets,
      "Closed surface to tets: drop separate pieces enclosing less than this fraction of the largest one's volume "
      "(specks of a segmentation), with a warning; 0 keeps them",
      [](Options& o) -> double& { return o.tetrahedralize.speck_fraction; }));
  r.push_back(settings::number<Options>("fineness", "", 0.0, 1.0, kTets,
                                        "Closed surface to tets: Netgen's fineness, 0 (coarse) .. 1 (fine)",
                                        [](Options& o) -> double& { return o.tetrahedralize.fineness; }));
  r.push_back(settings::number<Options>("grading", "", 0.0, 1.0, kTets,
                                        "Closed surface to tets: Netgen's grading, 0 (uniform) .. 1 (aggressive)",
                                        [](Options& o) -> double& { return o.tetrahedralize.grading; }));
  r.push_back(settings::integer<Options>("optimisation-steps", 0, 100, kTets,
                                         "Closed surface to tets: Netgen's volume optimisation passes",
                                         [](Options& o) -> int& { return o.tetrahedralize.optimisation_steps; }));
  return r;
}

}  // namespace

std::span<const settings::Setting<ModelOptions>> model_settings() {
  static const std::vector<settings::Setting<ModelOptions>> table = rows();
  return table;
}

}  // namespace hooke::calibrate
