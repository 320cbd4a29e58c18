// hooke mesh info MESH | convert IN OUT | tetrahedralize SURFACE -o VOLUME | from-image LABELS -o VOLUME: inspect,
// convert and fill meshes.
#include <algorithm>
#include <cstdio>
#include <hooke/calibrate/model_settings.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/units.hpp>
#include <hooke/image/label_mesh.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/io/mesher.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/mesh/tetrahedralize.hpp>
#include <hooke/mesh/topology.hpp>
#include <hooke/mesh/validate.hpp>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"

namespace hooke::cli {
namespace {

struct MeshOptions {
  std::string input, output, unit = "m", msh_version = "4.1";
  bool binary = false;
  GivenSettings tetrahedralize;   ///< calibrate::model_settings() rows of settings::kMesh
  std::vector<int> labels;        ///< from-image: the body's labels (empty: every label but 0)
  image::LabelMeshOptions image;  ///< from-image: smoothing (specks: --speck-fraction, a tet setting)
};

int run_info(const MeshOptions& o) {
  io::ReadOptions ro;
  ro.metres_per_unit = metres_per_unit(o.unit);
  ro.validate = false;
  mesh::Mesh m = io::read_mesh(o.input, ro);
  const mesh::ValidationReport v = mesh::validate(m);
  const auto lo = m.nodes.colwise().minCoeff().eval(), hi = m.nodes.colwise().maxCoeff().eval();
  double measure = 0.0, qmin = 1.0, qsum = 0.0;
  for (int e = 0; e < m.element_count(); ++e) {
    measure += mesh::element_measure(m, e);
    const double q = mesh::element_quality(m, e);
    qmin = std::min(qmin, q);
    qsum += q;
  }
  std::map<int, int> regions;
  for (int e = 0; e < m.element_count(); ++e) ++regions[m.region(e)];
  std::printf("%s\n  kind        %s (dim %d)\n  nodes       %d\n  elements    %d\n  edges       %zu\n", o.input.c_str(),
              std::string(mesh::element_kind_name(m.kind)).c_str(), m.dim(), m.node_count(), m.element_count(),
              mesh::unique_edges(m).size());
  std::printf("  bounds      [");
  for (int c = 0; c < m.dim(); ++c) std::printf("%s%.6g .. %.6g", c ? ", " : "", lo(c), hi(c));
  std::printf("] m\n  %s  %.6g %s\n", m.dim() == 3 && m.kind == mesh::ElementKind::kTet ? "volume    " : "area      ",
              measure, m.kind == mesh::ElementKind::kTet ? "m^3" : "m^2");
  std::printf("  quality     min %.4f, mean %.4f (1 = regular)\n", qmin, qsum / m.element_count());
  if (m.kind != mesh::ElementKind::kSurfaceTriangle)
    std::printf("  boundary    %lld facets\n", static_cast<long long>(mesh::boundary_facets(m).rows()));
  std::printf("  regions    ");
  for (const auto& [r, n] : regions) std::printf(" %d (%d elements)", r, n);
  std::printf("\n  reoriented  %d elements\n  unused      %zu nodes\n", v.reoriented_elements, v.unused_nodes.size());
  return 0;
}

int run_convert(const MeshOptions& o) {
  io::ReadOptions ro;
  ro.metres_per_unit = metres_per_unit(o.unit);
  const mesh::Mesh m = io::read_mesh(o.input, ro);
  io::WriteOptions wo;
  if (o.msh_version != "2.2" && o.msh_version != "4.1") throw InvalidArgument("--msh-version takes 2.2 or 4.1");
  wo.msh_version = o.msh_version == "2.2" ? io::MshVersion::kV22 : io::MshVersion::kV41;
  wo.binary = o.binary;
  io::write_mesh(o.output, m, wo);
  std::printf("wrote %s: %d nodes, %d %s elements (coordinates in m)\n", o.output.c_str(), m.node_count(),
              m.element_count(), std::string(mesh::element_kind_name(m.kind)).c_str());
  return 0;
}

mesh::TetrahedralizeOptions tetrahedralize_options(const GivenSettings& given, double metres_per_unit) {
  calibrate::ModelOptions o;
  settings::apply(calibrate::model_settings(), o, given, settings::kMesh, metres_per_unit);
  return o.tetrahedralize;
}

int run_tetrahedralize(const MeshOptions& o) {
  io::ReadOptions ro;
  ro.metres_per_unit = metres_per_unit(o.unit);
  mesh::TetrahedralizeReport r;
  const mesh::Mesh tets =
      io::tetrahedralize(io::read_mesh(o.input, ro), tetrahedralize_options(o.tetrahedralize, ro.metres_per_unit), &r);
  io::WriteOptions wo;
  wo.binary = o.binary;
  io::write_mesh(o.output, tets, wo);
  std::printf("hooke mesh tetrahedralize: %s\n  mesher      %s, surface %s, size %.4g m\n", o.input.c_str(),
              r.backend.c_str(), std::string(mesh::surface_meshing_name(r.options.surface)).c_str(),
              r.options.max_size);
  std::printf("  surface     %d nodes, %d triangles (%d reoriented), encloses %.6g m^3\n", r.surface_nodes,
              r.surface_triangles, r.flipped_triangles, r.surface_volume);
  if (r.closed_holes > 0 || r.dropped_pieces > 0)
    std::printf("  repaired    %d holes closed (%.4g m^2 added), %d specks dropped (%.4g m^3)\n", r.closed_holes,
                r.added_area, r.dropped_pieces, r.dropped_volume);
  std::printf("  tets        %d nodes, %d tets, volume %.6g m^3 (%+.3f %%)\n", r.nodes, r.tets, r.volume,
              100.0 * r.volume_error);
  std::printf("  fidelity    Hausdorff %.4g m (%.3f %% of the diagonal)%s\n", r.hausdorff, 100.0 * r.hausdorff_relative,
              r.surface_preserved ? ", surface nodes preserved" : "");
  std::printf(
      "  quality     radius ratio min %.4f (tet %d), mean %.4f; dihedral %.2f .. %.2f deg; %d slivers (< %.2g)\n",
      r.quality.min_radius_ratio, r.quality.worst_element, r.quality.mean_radius_ratio, r.quality.min_dihedral,
      r.quality.max_dihedral, r.slivers, mesh::kSliverRadiusRatio);
  std::printf("  time        %.2f s\n  wrote       %s\n", r.seconds, o.output.c_str());
  return 0;
}

int run_from_image(const MeshOptions& o) {
  image::LabelMeshOptions lo = o.image;
  lo.labels = o.labels;
  lo.tetrahedralize = tetrahedralize_options(o.tetrahedralize, 1.0);
  const image::LabelImage img = image::read_label_image(o.input);
  const image::LabelMesh m = image::labels_to_mesh(img, lo);
  io::WriteOptions wo;
  wo.binary = o.binary;
  io::write_mesh(o.output, m.tets, wo);
  const mesh::TetrahedralizeReport& r = m.meshing;
  std::printf("hooke mesh from-image: %s\n  image       %d x %d x %d voxels of %.4g x %.4g x %.4g mm\n",
              o.input.c_str(), img.size[0], img.size[1], img.size[2], 1e3 * img.spacing(0), 1e3 * img.spacing(1),
              1e3 * img.spacing(2));
  std::printf("  surface     %d triangles (%d coincident nodes welded, %d specks dropped: %.4g mm^3)\n",
              m.surface_triangles, m.welded_nodes, m.dropped_pieces, 1e9 * m.dropped_volume);
  std::printf("  tets        %d nodes, %d tets (%s, size %.4g m), volume %+.3f %% of the surface's\n", r.nodes, r.tets,
              r.backend.c_str(), r.options.max_size, 100.0 * r.volume_error);
  for (const image::LabelReport& l : m.labels)
    std::printf("  label %-5d %lld voxels (%.6g m^3), %d tets (%.6g m^3, %+.2f %%), smallest dihedral %.2f deg\n",
                l.label, static_cast<long long>(l.voxels), l.voxel_volume, l.tets, l.volume, 100.0 * l.volume_error,
                l.min_dihedral);
  if (m.unlabelled_tets > 0)
    std::printf("  unlabelled  %d tets had no sample point in a selected label (given label %d)\n", m.unlabelled_tets,
                m.labels.front().label);
  std::printf("  quality     radius ratio min %.4f, mean %.4f; %d slivers (< %.2g)\n", r.quality.min_radius_ratio,
              r.quality.mean_radius_ratio, r.slivers, mesh::kSliverRadiusRatio);
  std::printf("  time        %.2f s\n  wrote       %s\n", m.seconds, o.output.c_str());
  return 0;
}

}  // namespace

Action add_mesh_command(CLI::App& app) {
  auto o = std::make_shared<MeshOptions>();
  CLI::App* cmd = app.add_subcommand("mesh", "Inspect, convert and tetrahedralize meshes");
  cmd->require_subcommand(1);
  CLI::App* info = cmd->add_subcommand("info", "Print counts, bounds, measure, quality and validation of a mesh");
  info->add_option("mesh", o->input, "Mesh file")->required();
  info->add_option("--unit", o->unit, "Length unit of the file: m, cm, mm, um")->capture_default_str();
  CLI::App* convert = cmd->add_subcommand("convert", "Convert between formats (by extension); output in metres");
  convert->add_option("input", o->input, "Input mesh")->required();
  convert->add_option("output", o->output, "Output mesh (.msh, .vtu, .node/.ele, .obj, .off, .stl)")->required();
  convert->add_option("--unit", o->unit, "Length unit of the input: m, cm, mm, um")->capture_default_str();
  convert->add_option("--msh-version", o->msh_version, "2.2 or 4.1")->capture_default_str();
  convert->add_flag("--binary", o->binary, "Binary .msh / .stl");
  CLI::App* tet = cmd->add_subcommand(
      "tetrahedralize", "Fill a closed triangle surface (a scan's STL/OFF) with tets (Netgen), with a quality report");
  tet->add_option("surface", o->input, "Closed surface (.stl, .off, .obj, or any mesh file of surface triangles)")
      ->required();
  tet->add_option("-o,--output", o->output, "Tet mesh to write (.msh, .vtu, .node/.ele)")->required();
  tet->add_option("--unit", o->unit, "Length unit of the surface file: m, cm, mm, um")->capture_default_str();
  tet->add_flag("--binary", o->binary, "Binary .msh");
  add_settings(tet, settings::describe(calibrate::model_settings(), settings::kMesh), o->tetrahedralize,
               "Closed surface to tets");
  CLI::App* from_image = cmd->add_subcommand(
      "from-image",
      "Mesh the labels of a segmentation (.nii, .nii.gz, .nrrd, .nhdr, .mha, .mhd; spacing in mm) into tets "
      "whose region is their label, with a report per label (docs/images.md)");
  from_image->add_option("image", o->input, "Label image")->required();
  from_image->add_option("-o,--output", o->output, "Tet mesh to write (.msh, .vtu, .node/.ele): region = label")
      ->required();
  from_image->add_option("--labels", o->labels, "The body's labels, comma-separated (default: every label but 0)")
      ->delimiter(',');
  from_image
      ->add_option("--smoothing", o->image.smoothing,
                   "Gaussian sigma before the surface is extracted, in (averaged) voxels")
      ->capture_default_str();
  from_image
      ->add_option("--surface-smoothing", o->image.surface_smoothing,
                   "Taubin smoothing iterations of the extracted surface")
      ->capture_default_str();
  from_image->add_flag("--binary", o->binary, "Binary .msh");
  add_settings(from_image, settings::describe(calibrate::model_settings(), settings::kMesh), o->tetrahedralize,
               "Surface to tets");
  return [o, info, tet, from_image] {
    if (info->parsed()) return run_info(*o);
    if (from_image->parsed()) return run_from_image(*o);
    return tet->parsed() ? run_tetrahedralize(*o) : run_convert(*o);
  };
}

}  // namespace hooke::cli
