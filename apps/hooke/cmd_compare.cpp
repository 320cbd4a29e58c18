// hooke compare MESH --young PA --poisson NU --method NAME --load CASE (--traction PA | --strain S) [-o DIR]:
// a calibrated spring model against the FEM reference on one load case.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <hooke/core/error.hpp>
#include <hooke/core/units.hpp>
#include <hooke/experiments/compare.hpp>
#include <hooke/experiments/figure.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/io/vtu.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/surface/closed_surface.hpp>
#include <memory>
#include <string>

#include "commands.hpp"
#include "plot.hpp"

namespace hooke::cli {
namespace {

struct CompareCli {
  ModelInput in;
  std::string method = "lloyd-tet", load = "stretch", reference = "linear", out_dir, plane = "stress";
  SurfaceInput surface;
  int layers = 4;
  bool no_figure = false;
  double traction = std::nan(""), strain = std::nan("");
};

int run_compare(const CompareCli& o) {
  io::ReadOptions ro;
  ro.metres_per_unit = metres_per_unit(o.in.unit);
  const mesh::Mesh m = io::read_mesh(o.in.mesh_path, ro);
  material::Material mat{material::Law::kLinear, o.in.young, o.in.poisson,
                         o.plane == "strain" ? material::Plane::kStrain : material::Plane::kStress, o.in.thickness};
  material::validate(mat);
  if (std::isnan(o.traction) == std::isnan(o.strain))
    throw InvalidArgument("give exactly one of --traction and --strain");
  experiments::CompareOptions co;
  if (o.method != "surface") co.method = calibrate::method_from_name(o.method);
  co.load = experiments::load_kind_from_name(o.load);
  co.reference = material::law_from_name(o.reference);
  co.traction_pa = std::isnan(o.traction) ? 0.0 : o.traction;
  co.strain = std::isnan(o.strain) ? 0.0 : o.strain;
  const bool surface = o.method == "surface";
  experiments::Comparison c;
  mesh::Mesh fem_mesh = m;
  if (surface) {
    // Arnab & Raja's surface model against the FEM of the radially tetrahedralised volume.
    const calibrate::SurfaceOptions so = surface_options(o.surface);
    c = experiments::compare_surface(m, mat, so, co, o.layers);
    surface::check_closed_surface(fem_mesh);
    fem_mesh =
        mesh::tetrahedralise_radially(fem_mesh, so.centre ? *so.centre : surface::volume_centroid(fem_mesh), o.layers);
  } else {
    c = experiments::compare(m, {mat}, co);
  }
  const double to_unit = 1.0 / ro.metres_per_unit;
  if (surface)
    std::printf("hooke compare: %s, surface model (scheme %s) vs %s FEM of %d tets, %s, traction %.6g Pa\n",
                o.in.mesh_path.c_str(), o.surface.scheme.c_str(), o.reference.c_str(), fem_mesh.element_count(),
                o.load.c_str(), c.load.traction_pa);
  else
    std::printf("hooke compare: %s, %s springs (%zu) vs %s FEM, %s, traction %.6g Pa\n", o.in.mesh_path.c_str(),
                o.method.c_str(), c.springs.pairs.size(), o.reference.c_str(), o.load.c_str(), c.load.traction_pa);
  std::printf("  fem       %s: %s\n", std::string(solve::status_name(c.fem_report.status)).c_str(),
              c.fem_report.message.c_str());
  std::printf("  springs   %s: %s\n", std::string(solve::status_name(c.spring_report.status)).c_str(),
              c.spring_report.message.c_str());
  solve::require_converged(c.fem_report);
  solve::require_converged(c.spring_report);
  std::printf("  error     max %.4g %s (%.3f %% of height), mean %.4g %s (%.3f %% of height)\n", c.max_error * to_unit,
              o.in.unit.c_str(), 100.0 * c.max_error / c.load.height, c.mean_error * to_unit, o.in.unit.c_str(),
              100.0 * c.mean_error / c.load.height);
  if (!o.out_dir.empty()) {
    std::filesystem::create_directories(o.out_dir);
    const VecX rest = Eigen::Map<const VecX>(m.nodes.data(), m.nodes.size());
    const std::string path = (std::filesystem::path(o.out_dir) / "compare.vtu").string();
    io::write_vtu(path, m,
                  {{"fem_displacement", m.dim(), c.fem_positions - rest},
                   {"spring_displacement", m.dim(), c.spring_positions - rest},
                   {"node_error", 1, c.node_error}});
    std::printf("  wrote     %s\n", path.c_str());
    char title[160];
    std::snprintf(title, sizeof title, "%s, %s vs %s FEM\nmax %.3g cm, mean %.3g cm", o.load.c_str(), o.method.c_str(),
                  o.reference.c_str(), 100.0 * c.max_error, 100.0 * c.mean_error);
    experiments::Figure fig{
        "compare",
        std::filesystem::path(o.in.mesh_path).filename().string() + " (MSM red, FEM black)",
        {experiments::deformation_panel(title, fem_mesh, c.fem_mesh_positions, m, c.spring_positions)}};
    experiments::write_figure_spec(o.out_dir, fig);
    if (!o.no_figure) {
      plot_figures({std::filesystem::path(o.out_dir) / "compare.json"});
      std::printf("  wrote     %s\n", (std::filesystem::path(o.out_dir) / "compare.png").string().c_str());
    }
  }
  return 0;
}

}  // namespace

Action add_compare_command(CLI::App& app) {
  auto o = std::make_shared<CompareCli>();
  CLI::App* cmd = app.add_subcommand("compare", "Compare a calibrated spring model with the FEM reference");
  add_model_input_options(cmd, o->in);
  cmd->add_option("--method", o->method,
                  "Calibration method (vangelder, lloyd-equilateral, lloyd-triangle, lloyd-square, "
                  "lloyd-tet, lloyd-tet-volume, stiffness-fit, stiffness-fit-volume), or surface for Arnab & "
                  "Raja's surface model of a closed triangle surface")
      ->capture_default_str();
  add_surface_options(cmd, o->surface);
  cmd->add_option("--layers", o->layers, "surface: layers of the radial tetrahedralisation for the FEM")
      ->capture_default_str();
  cmd->add_option("--load", o->load, "stretch, compress or shear")->capture_default_str();
  cmd->add_option("--traction", o->traction, "Traction on the top boundary, Pa");
  cmd->add_option("--strain", o->strain, "Traction giving this mean top strain in the linear FEM");
  cmd->add_option("--reference", o->reference, "FEM law: linear, stvk or neohookean")->capture_default_str();
  cmd->add_option("--plane", o->plane, "2D model: stress or strain")->capture_default_str();
  cmd->add_option("-o,--output", o->out_dir,
                  "Folder for compare.vtu (both displacement fields and the node error) and compare.png");
  cmd->add_flag("--no-figure", o->no_figure, "Write the figure spec compare.json but do not run matplotlib");
  return [o] { return run_compare(*o); };
}

}  // namespace hooke::cli
