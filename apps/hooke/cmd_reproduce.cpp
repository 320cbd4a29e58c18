// hooke reproduce lloyd2007|arnab2008|nu-range [-o DIR] [--no-figures] [--scheduler ADDRESS|local]: a paper's
// experiments with a report; nu-range's comparisons optionally as Dask tasks (hooke.batch).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <hooke/core/atomic_file.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/log.hpp>
#include <hooke/core/output_transaction.hpp>
#include <hooke/core/settings.hpp>
#include <hooke/experiments/nu_range.hpp>
#include <hooke/experiments/reproduce_arnab2008.hpp>
#include <hooke/experiments/reproduce_lloyd2007.hpp>
#include <memory>
#include <string>

#include "commands.hpp"
#include "python.hpp"

#ifndef HOOKE_MESH_DIR
#define HOOKE_MESH_DIR "data/meshes"
#endif

namespace hooke::cli {
namespace {

// The spec files a report wrote for `figures` under `dir`/figures/.
std::vector<std::filesystem::path> figure_specs(const std::string& dir,
                                                const std::vector<experiments::Figure>& figures) {
  std::vector<std::filesystem::path> specs;
  for (const auto& f : figures) specs.push_back(std::filesystem::path(dir) / "figures" / (f.name + ".json"));
  return specs;
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw IoError("cannot read " + path.string());
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The study's rows computed as Dask tasks by hooke.batch (in the serial study's order), then its report here.
experiments::NuRangeReport nu_range_on_dask(const std::string& mesh_dir, const experiments::NuRangeOptions& options,
                                            const std::string& scheduler) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::filesystem::path scratch =
      std::filesystem::temp_directory_path() / ("hooke-nu-range-" + std::to_string(getpid()));
  std::filesystem::create_directories(scratch);
  struct Cleanup {
    std::filesystem::path dir;
    ~Cleanup() {
      std::error_code ec;
      std::filesystem::remove_all(dir, ec);
    }
  } cleanup{scratch};
  write_file_atomically(scratch / "options.json",
                        [&](std::ostream& out) { out << experiments::nu_range_options_json(options); });
  const int rc = run_python({"-m", "hooke.batch", "--nu-range-rows", (scratch / "options.json").string(), "--meshes",
                             mesh_dir, "-o", (scratch / "rows.json").string(), "--scheduler", scheduler});
  if (rc != 0) throw IoError("the nu-range study on Dask (hooke.batch) failed with exit code " + std::to_string(rc));
  return experiments::nu_range_report(options, experiments::nu_range_rows_from_json(read_text(scratch / "rows.json")),
                                      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

// --laws: "none", or LAW:STRAIN entries (neohookean:0.2).
std::vector<experiments::NuRangeLaw> law_regimes(const std::vector<std::string>& items) {
  std::vector<experiments::NuRangeLaw> out;
  if (items.size() == 1 && items.front() == "none") return out;
  for (const std::string& item : items) {
    const std::size_t colon = item.find(':');
    if (colon == std::string::npos)
      throw InvalidArgument("--laws: '" + item + "' is not LAW:STRAIN (neohookean:0.2) or none");
    out.push_back({item.substr(0, colon), settings::parse_number("--laws strain", item.substr(colon + 1))});
  }
  return out;
}

}  // namespace

Action add_reproduce_command(CLI::App& app) {
  struct Options {
    std::string paper, out_dir, mesh_dir = HOOKE_MESH_DIR, scheduler;
    std::vector<std::string> laws;
    bool no_figures = false;
    experiments::NuRangeOptions nu_range;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("reproduce", "Reproduce a paper's experiments and write a report");
  cmd->add_option("paper", o->paper, "lloyd2007, arnab2008, or nu-range (the study of every method over nu)")
      ->required();
  cmd->add_option("-o,--output", o->out_dir, "Report folder (default out/<paper>)");
  cmd->add_option("--meshes", o->mesh_dir, "Folder of the committed meshes")->capture_default_str();
  cmd->add_flag("--no-figures", o->no_figures, "Write the figure specs (JSON) but do not run matplotlib");
  cmd->add_option("--nu", o->nu_range.poisson, "nu-range: Poisson's ratios")->delimiter(',')->capture_default_str();
  cmd->add_option("--methods", o->nu_range.methods, "nu-range: calibration methods for tet meshes")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--triangle-methods", o->nu_range.triangle_methods,
                  "nu-range: calibration methods for triangle meshes")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--planes", o->nu_range.planes, "nu-range: the 2D reductions triangle meshes run in (stress, strain)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--study-meshes", o->nu_range.meshes, "nu-range: committed meshes")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--large-strain", o->nu_range.large_strain, "nu-range: the large-deformation strain (0: none)")
      ->capture_default_str();
  cmd->add_option("--laws", o->laws,
                  "nu-range: the law regimes, LAW:STRAIN (displacement control, Hookean and fitted terms), or none")
      ->delimiter(',')
      ->default_str("neohookean:0.2,stvk:0.12");
  cmd->add_option("--fit-refinements", o->nu_range.fit_refinements,
                  "nu-range: the law fit's pattern-search steps (1/2, 1/4, ...)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--scheduler", o->scheduler,
                  "nu-range: run the comparisons as Dask tasks (hooke.batch, docs/batch.md) on the scheduler at this "
                  "address (tcp://host:8786), or 'local' for a local cluster of one worker per core; same report");
  return [o] {
    if (o->out_dir.empty()) o->out_dir = "out/" + o->paper;
    if (!o->laws.empty()) o->nu_range.laws = law_regimes(o->laws);
    if (o->paper != "lloyd2007" && o->paper != "arnab2008" && o->paper != "nu-range")
      throw InvalidArgument("unknown paper '" + o->paper + "' (available: lloyd2007, arnab2008, nu-range)");
    // One transaction: report and figures are written into a staging folder and moved into place with the
    // report (.md) last, so a run killed at any instant leaves the previous report whole, with its figures.
    if (!o->scheduler.empty() && o->paper != "nu-range")
      throw InvalidArgument("--scheduler runs the nu-range study only; " + o->paper + " runs here");
    OutputTransaction outputs;
    const std::string staging = outputs.stage_folder(o->out_dir).string();
    if (o->paper == "nu-range") {
      const LogSink previous = set_log_sink([](LogLevel level, std::string_view message) {
        std::fprintf(level >= LogLevel::kWarning ? stderr : stdout, "%.*s\n", static_cast<int>(message.size()),
                     message.data());
        std::fflush(stdout);
      });
      const auto report = o->scheduler.empty() ? experiments::reproduce_nu_range(o->mesh_dir, o->nu_range)
                                               : nu_range_on_dask(o->mesh_dir, o->nu_range, o->scheduler);
      set_log_sink(previous);
      experiments::write_nu_range_report(staging, report);
      for (const auto& r : report.recommendations) std::printf("pick %s\n", r.c_str());
      if (!o->no_figures) plot_figures(figure_specs(staging, report.figures));
      outputs.commit({"nu_range.json", "method_table.inc", "nu_range.md"});
      std::printf("wrote %s/nu_range.md, nu_range.json, method_table.inc and %zu figures (%.0f s)\n",
                  o->out_dir.c_str(), report.figures.size(), report.seconds);
      return 0;
    }
    if (o->paper == "arnab2008") {
      const auto report = experiments::reproduce_arnab2008();
      experiments::write_arnab2008_report(staging, report);
      for (const auto& row : report.table1)
        std::printf("Table 1: cube %4d nodes, E %6g Pa: scheme D %8.2f Pa (%+.2f %%), paper %g Pa\n", row.nodes,
                    row.youngs_modulus, row.extracted_d, row.deviation_percent, row.paper);
      for (const auto& row : report.table2)
        std::printf("Table 2: %-12s surface %7.0f steps/s, volume %7.0f steps/s (dt %.3g ms); paper %g / %g FPS\n",
                    row.model.c_str(), row.surface_steps_per_second, row.volume_steps_per_second, row.dt * 1e3,
                    row.paper_surface_fps, row.paper_volume_fps);
      std::printf("experiments: %.1f s\n", report.seconds);
      if (!o->no_figures) plot_figures(figure_specs(staging, report.figures));
      outputs.commit({"arnab2008.json", "arnab2008.md"});
      std::printf("wrote %s/arnab2008.md, arnab2008.json and %zu figures\n", o->out_dir.c_str(), report.figures.size());
      return 0;
    }
    const auto report = experiments::reproduce_lloyd2007(o->mesh_dir);
    experiments::write_lloyd2007_report(staging, report);
    for (const auto& c : report.cases)
      std::printf("%-42s %-18s ours %7.3f / %6.3f cm   paper %6.3f / %6.3f cm   fit %6.3f / %6.3f cm   %s\n",
                  c.id.c_str(), c.method.substr(0, 18).c_str(), c.max_error_cm, c.mean_error_cm, c.paper_max_cm,
                  c.paper_mean_cm, c.fit_max_error_cm, c.fit_mean_error_cm, c.status.c_str());
    std::printf("Fig. 1 triangle: stiffness stretch %.4f N/m, compression %.4f N/m; square: %.4f, %.4f N/m\n",
                report.triangle.stretch_stiffness, report.triangle.compress_stiffness, report.square.stretch_stiffness,
                report.square.compress_stiffness);
    std::printf("experiments: %.1f s\n", report.seconds);
    if (!o->no_figures) plot_figures(figure_specs(staging, report.figures));
    outputs.commit({"lloyd2007.json", "lloyd2007.md"});
    std::printf("wrote %s/lloyd2007.md, lloyd2007.json and %zu figures\n", o->out_dir.c_str(), report.figures.size());
    return 0;
  };
}

}  // namespace hooke::cli
