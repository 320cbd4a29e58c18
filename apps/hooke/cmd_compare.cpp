// hooke compare (MESH --young PA --poisson NU --method NAME | --model MODEL.json) --load CASE
// (--traction PA | --strain S) [-o DIR]: a calibrated model against the FEM reference on one load case; with
// --tool SHAPE --press F, under the same contact instead: the tool pressed into the top to F x the height.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <hooke/core/atomic_file.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/output_transaction.hpp>
#include <hooke/core/units.hpp>
#include <hooke/experiments/compare.hpp>
#include <hooke/experiments/contact_comparison.hpp>
#include <hooke/experiments/figure.hpp>
#include <hooke/io/vtu.hpp>
#include <memory>
#include <string>

#include "commands.hpp"
#include "python.hpp"

namespace hooke::cli {
namespace {

struct CompareCli {
  ModelSource in;
  std::string load = "stretch", reference = "linear", control = "traction", out_dir;
  int layers = 4;
  bool no_figure = false;
  double traction = std::nan(""), strain = std::nan("");
  std::string tool;  ///< --tool: compare under contact
  double press = 0.2, contact_distance = 0.0;
  int press_steps = 8;
};

// --tool: the tool, centred over the top face's centre and touching it, pressed down to press x height; a row per
// step, then refusal (exit 3) when a model has no stable equilibrium (the experiment throws SolverFailure).
int run_contact_compare(const CompareCli& o) {
  const calibrate::CalibratedModel model = load_model(o.in);
  const contact::RigidTool tool = contact::parse_tool(o.tool, metres_per_unit(o.in.unit));
  if (!(o.press > 0.0 && o.press < 1.0)) throw InvalidArgument("--press must be in (0, 1) (a fraction of the height)");
  const RowMatX& x = model.mesh.nodes;
  const Vec3 lo = x.colwise().minCoeff().transpose(), hi = x.colwise().maxCoeff().transpose();
  const double height = hi.z() - lo.z();
  experiments::ContactPressOptions co;
  const double reach =
      tool.shape() == contact::ToolShape::kCapsule ? tool.radius() + 0.5 * tool.length() : tool.radius();
  co.start.position = Vec3(0.5 * (lo.x() + hi.x()), 0.5 * (lo.y() + hi.y()), hi.z() + reach);
  co.depth = o.press * height;
  co.steps = o.press_steps;
  co.contact_distance = o.contact_distance;
  co.reference = material::law_from_name(o.reference);
  const auto rows = experiments::compare_under_contact(model, tool, co);
  std::printf("hooke compare: %s, %s model vs %s FEM under %s pressed into the top to %.4g %% of the height\n",
              model.mesh.source.c_str(), model.method.c_str(), o.reference.c_str(), tool.description().c_str(),
              100.0 * o.press);
  std::printf("  %-10s %-12s %-12s %-11s %-11s %-9s %s\n", "depth (%)", "fem F (N)", "model F (N)", "F error",
              "rel. L2", "contacts", "smallest gap (m)");
  double worst_force = 0.0, worst_l2 = 0.0;
  for (const experiments::ContactPressRow& r : rows) {
    std::printf("  %-10.4g %-12.6g %-12.6g %-11.4g %-11.4g %3d/%-5d %.3g\n", 100.0 * r.travel / height,
                r.fem_force.dot(-co.direction), r.model_force.dot(-co.direction), r.force_error, r.relative_l2,
                r.fem_contacts, r.model_contacts, r.smallest_gap);
    worst_force = std::max(worst_force, r.force_error);
    worst_l2 = std::max(worst_l2, r.relative_l2);
  }
  std::printf("  worst     force error %.4g, relative L2 %.4g\n", worst_force, worst_l2);
  return 0;
}

void print_comparison(const CompareCli& o, const calibrate::CalibratedModel& model, const experiments::Comparison& c) {
  const double to_unit = 1.0 / metres_per_unit(o.in.unit);
  const std::string label = model.surface
                                ? "surface model (scheme " + model.surface->scheme + ")"
                                : model.method + " model (" + std::to_string(model.springs.pairs.size()) + " springs)";
  if (c.load.control == model::LoadControl::kDisplacement)
    std::printf("hooke compare: %s, %s vs %s FEM of %d elements, %s, top moved %.6g %s (%.4g %% of height)\n",
                model.mesh.source.c_str(), label.c_str(), o.reference.c_str(), c.fem_mesh.element_count(),
                o.load.c_str(), c.load.displacement * to_unit, o.in.unit.c_str(),
                100.0 * c.load.displacement / c.load.height);
  else
    std::printf("hooke compare: %s, %s vs %s FEM of %d elements, %s, traction %.6g Pa\n", model.mesh.source.c_str(),
                label.c_str(), o.reference.c_str(), c.fem_mesh.element_count(), o.load.c_str(), c.load.traction_pa);
  std::printf("  fem       %s: %s\n", std::string(solve::status_name(c.fem_report.status)).c_str(),
              c.fem_report.message.c_str());
  std::printf("  springs   %s: %s\n", std::string(solve::status_name(c.spring_report.status)).c_str(),
              c.spring_report.message.c_str());
  // Under traction control a model that loses stability or stops short has a limit load below the one asked for.
  const auto limit = [&](const solve::SolveReport& r, const char* who) {
    const double factor = r.critical_load_factor > 0.0 ? r.critical_load_factor : r.load_factor;
    if (c.load.control == model::LoadControl::kTraction && r.status != solve::SolveStatus::kConverged)
      std::printf("  limit     %s: %.4g of the load (%.6g Pa)\n", who, factor, factor * c.load.traction_pa);
  };
  limit(c.fem_report, "fem");
  limit(c.spring_report, "springs");
  solve::require_converged(c.fem_report);
  solve::require_converged(c.spring_report);
  std::printf("  force     on the top: fem %.6g N, model %.6g N along the load, relative error %.4g\n",
              c.fem_reaction.dot(c.load.direction), c.spring_reaction.dot(c.load.direction), c.reaction_error);
  std::printf("  error     max %.4g %s (%.3f %% of height), mean %.4g %s (%.3f %% of height), relative L2 %.4g\n",
              c.max_error * to_unit, o.in.unit.c_str(), 100.0 * c.max_error / c.load.height, c.mean_error * to_unit,
              o.in.unit.c_str(), 100.0 * c.mean_error / c.load.height, c.relative_l2);
}

// compare.vtu, compare.json and compare.png into the staging folder `dir` (moved into -o DIR by the caller).
void write_outputs(const CompareCli& o, const calibrate::CalibratedModel& model, const experiments::Comparison& c,
                   const std::filesystem::path& dir) {
  const mesh::Mesh& m = model.mesh;
  const VecX rest = Eigen::Map<const VecX>(m.nodes.data(), m.nodes.size());
  io::write_vtu(dir / "compare.vtu", m,
                {{"fem_displacement", m.dim(), c.fem_positions - rest},
                 {"spring_displacement", m.dim(), c.spring_positions - rest},
                 {"node_error", 1, c.node_error}});
  char title[160];
  std::snprintf(title, sizeof title, "%s, %s vs %s FEM\nmax %.3g cm, mean %.3g cm", o.load.c_str(),
                model.method.c_str(), o.reference.c_str(), 100.0 * c.max_error, 100.0 * c.mean_error);
  experiments::Figure fig{
      "compare",
      std::filesystem::path(m.source).filename().string() + " (MSM red, FEM black)",
      {experiments::deformation_panel(title, c.fem_mesh, c.fem_mesh_positions, m, c.spring_positions)}};
  experiments::write_figure_spec(dir, fig);
  if (!o.no_figure) plot_figures({dir / "compare.json"});
}

int run_compare(const CompareCli& o) {
  if (!o.tool.empty()) {
    if (!std::isnan(o.traction) || !std::isnan(o.strain) || !o.out_dir.empty())
      throw InvalidArgument("--tool compares under contact: it takes --press, not --traction, --strain or -o");
    return run_contact_compare(o);
  }
  if (std::isnan(o.traction) == std::isnan(o.strain))
    throw InvalidArgument("give exactly one of --traction and --strain");
  if (!std::isnan(o.strain) && !(o.strain > 0.0)) throw InvalidArgument("--strain must be > 0");
  // Outputs as one transaction: the folder is checked and staged before the work, and nothing reaches it
  // unless everything, the figure included, was written.
  OutputTransaction outputs;
  const std::filesystem::path staging = o.out_dir.empty() ? std::filesystem::path() : outputs.stage_folder(o.out_dir);
  const calibrate::CalibratedModel model = load_model(o.in);
  experiments::CompareOptions co;
  co.load = model::load_kind_from_name(o.load);
  co.reference = material::law_from_name(o.reference);
  co.traction_pa = std::isnan(o.traction) ? 0.0 : o.traction;
  co.strain = std::isnan(o.strain) ? 0.0 : o.strain;
  co.control = model::load_control_from_name(o.control);
  if (co.control == model::LoadControl::kDisplacement && std::isnan(o.strain))
    throw InvalidArgument("--control displacement needs --strain (the top is moved by strain x height)");
  const experiments::Comparison c = experiments::compare_calibrated(model, co, o.layers);
  print_comparison(o, model, c);
  if (o.out_dir.empty()) return 0;
  write_outputs(o, model, c, staging);
  outputs.commit({"compare.vtu"});
  std::printf("  wrote     %s/compare.vtu%s\n", o.out_dir.c_str(), o.no_figure ? "" : " and compare.png");
  return 0;
}

}  // namespace

Action add_compare_command(CLI::App& app) {
  auto o = std::make_shared<CompareCli>();
  CLI::App* cmd = app.add_subcommand("compare", "Compare a calibrated model with the FEM reference");
  add_model_source_options(cmd, o->in, settings::kCompare);
  cmd->add_option("--layers", o->layers, "surface: layers of the radial tetrahedralisation for the FEM")
      ->capture_default_str();
  cmd->add_option("--load", o->load, "stretch, compress or shear")->capture_default_str();
  cmd->add_option("--traction", o->traction, "Traction on the top boundary, Pa");
  cmd->add_option("--strain", o->strain, "Traction giving this mean top strain in the linear FEM");
  cmd->add_option("--reference", o->reference, "FEM law: linear, stvk or neohookean")->capture_default_str();
  cmd->add_option("--control", o->control,
                  "traction (a dead load on the top) or displacement (the top moved by strain x height; the force "
                  "on it compared)")
      ->capture_default_str();
  cmd->add_option("-o,--output", o->out_dir,
                  "Folder for compare.vtu (both displacement fields and the node error) and compare.png");
  cmd->add_flag("--no-figure", o->no_figure, "Write the figure spec compare.json but do not run matplotlib");
  cmd->add_option("--tool", o->tool,
                  "Compare under contact instead (docs/contact.md): sphere:R or capsule:R,L (in --unit), centred over "
                  "the top and pressed into it; the force on it and the displacement field at every step");
  cmd->add_option("--press", o->press, "With --tool: how far it presses, a fraction of the height")
      ->capture_default_str();
  cmd->add_option("--press-steps", o->press_steps, "With --tool: equal steps of the press")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_option("--contact-distance", o->contact_distance,
                  "With --tool: the barrier's activation distance, m (0: 1 % of the mean boundary edge)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  return [o] { return run_compare(*o); };
}

}  // namespace hooke::cli
