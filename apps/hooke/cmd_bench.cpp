// hooke bench [--sizes 1k,10k,100k] [--methods M,...] [--poisson NU] [--steps N] [--drag M] [--integrators R,...]
// [--all] [-o DIR] [--haptics [--haptic-stiffness S] [--deformation-dt S]]: the dynamics benchmark table (ms/step per
// integrator, mesh and model with its error against a converged implicit step, spring-force throughput beside the
// in-run bandwidth bound; by default the real-time path only, --all every row; a progress line per row on standard
// error). Bullet's ratio needs the Google Benchmark peer: build/release/bench/hooke_bench
// --benchmark_filter=Peer. --haptics: the multirate haptics benchmark instead (interactive::run_haptics_benchmark).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <hooke/calibrate/model_settings.hpp>
#include <hooke/core/atomic_file.hpp>
#include <hooke/core/error.hpp>
#include <hooke/experiments/dynamics_benchmark.hpp>
#include <hooke/interactive/haptics_benchmark.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "commands.hpp"

namespace hooke::cli {
namespace {

// Without --all the table covers the real-time path (the quasi-newton step the viewer and the haptic loop run) for
// the two models the real-time targets name; --all gives every integrator for every default method.
const std::vector<std::string> kRealTimeMethods{"any-nu-tet", "stiffness-fit-volume"};
const std::vector<std::string> kRealTimeRows{"quasi-newton (rest)"};

struct BenchCli {
  std::vector<std::string> sizes{"1k", "10k"};
  experiments::DynamicsBenchmarkOptions options;
  bool all = false;
  bool methods_given = false, rows_given = false;
  GivenSettings model;  ///< calibrate::model_settings() rows of settings::kBench (the term law)
  std::string out_dir;
  bool haptics = false;
  std::string haptic_stiffness = "secant";
  bool haptic_curvature = true;
  double deformation_dt = 0.0;
  double reference_budget = 900.0;
  double ramp = 1.0, hold = 0.3;
  std::string qn_hessian = "rest";
  double qn_tolerance = interactive::kDeformationTolerance;
  int qn_iterations = solve::QuasiNewtonOptions{}.max_iterations;
};

// The multirate haptics benchmark on the same sizes, with the first method and the same nu and drag.
int run_haptics(const BenchCli& o, const std::vector<int>& sizes) {
  interactive::HapticsBenchmarkOptions h;
  h.sizes = sizes;
  h.method = o.options.methods.empty() ? h.method : o.options.methods.front();
  h.poisson = o.options.poisson;
  h.drag = o.options.drag;
  h.tool_radius = o.options.tool_radius;
  h.tool_press = o.options.tool_press;
  h.stiffness = interactive::haptic_stiffness_from_name(o.haptic_stiffness);
  h.curvature = o.haptic_curvature;
  h.deformation_dt = o.deformation_dt;
  h.reference_budget = o.reference_budget;
  h.ramp = o.ramp;
  h.simulator.quasi_newton.initial_hessian = solve::quasi_newton_hessian_from_name(o.qn_hessian);
  h.simulator.quasi_newton.tolerance = o.qn_tolerance;
  h.simulator.quasi_newton.max_iterations = o.qn_iterations;
  h.hold = o.hold;
  const interactive::HapticsBenchmarkReport report = interactive::run_haptics_benchmark(h);
  const std::string markdown = interactive::haptics_benchmark_markdown(h, report);
  std::printf("hooke bench --haptics: multirate haptics (%s stiffness), %s\n\n%s", o.haptic_stiffness.c_str(),
              h.tool_radius > 0.0 ? "a sphere pressed into the top's centre" : "the top's centre dragged",
              markdown.c_str());
  if (!o.out_dir.empty()) {
    const std::filesystem::path dir(o.out_dir);
    create_output_folder(dir);
    write_file_atomically(dir / "haptics.md", [&](std::ostream& out) { out << markdown; });
    std::printf("wrote %s\n", (dir / "haptics.md").string().c_str());
  }
  return 0;
}

int run_bench(const BenchCli& o) {
  experiments::DynamicsBenchmarkOptions options = o.options;
  calibrate::ModelOptions model;
  model.spring_exponent = options.spring_exponent;
  model.volume_exponent = options.volume_exponent;
  settings::apply(calibrate::model_settings(), model, o.model, settings::kBench);
  options.spring_exponent = model.spring_exponent;
  options.volume_exponent = model.volume_exponent;
  options.sizes.clear();
  for (const std::string& s : o.sizes) {
    if (s == "1k")
      options.sizes.push_back(0);
    else if (s == "10k")
      options.sizes.push_back(1);
    else if (s == "100k")
      options.sizes.push_back(2);
    else
      throw InvalidArgument("--sizes takes 1k, 10k and 100k, not '" + s + "'");
  }
  if (o.haptics) return run_haptics(o, options.sizes);
  if (!o.all && !o.methods_given) options.methods = kRealTimeMethods;
  if (!o.all && !o.rows_given) options.integrators = kRealTimeRows;
  options.progress = [](const std::string& line) { std::fprintf(stderr, "hooke bench: %s\n", line.c_str()); };
  const experiments::DynamicsBenchmarkReport report = experiments::run_dynamics_benchmark(options);
  const std::string markdown = experiments::dynamics_benchmark_markdown(report);
  char load[96];
  if (options.tool_radius > 0.0)
    std::snprintf(load, sizeof load, "a %g mm sphere pressed into the top %g %% of the height",
                  1e3 * options.tool_radius, 100.0 * options.tool_press);
  else if (options.press > 0.0)
    std::snprintf(load, sizeof load, "the top pressed %g %% of the height", 100.0 * options.press);
  else
    std::snprintf(load, sizeof load, "the top's centre dragged %g mm", 1e3 * options.drag);
  std::printf(
      "hooke bench: tet cylinders, nu = %g, spring / volume exponents %g / %g, gravity, bottom clamped, %s\n\n%s",
      options.poisson, options.spring_exponent, options.volume_exponent, load, markdown.c_str());
  std::printf("\nBullet's soft body at the same dt: build/release/bench/hooke_bench --benchmark_filter=Peer\n");
  if (!o.out_dir.empty()) {
    const std::filesystem::path dir(o.out_dir);
    create_output_folder(dir);
    write_file_atomically(dir / "bench.md", [&](std::ostream& out) { out << markdown; });
    nlohmann::json j;
    j["triad_gbps"] = report.triad_gbps;
    for (const auto& t : report.springs)
      j["springs"].push_back({{"nodes", t.nodes},
                              {"springs", t.springs},
                              {"ns_per_spring", t.ns_per_spring},
                              {"bandwidth_fraction", t.bandwidth_fraction}});
    for (const auto& t : report.steps)
      j["steps"].push_back({{"nodes", t.nodes},
                            {"method", t.method},
                            {"integrator", t.integrator},
                            {"dt", t.dt},
                            {"median_ms", t.median_ms},
                            {"p95_ms", t.p95_ms},
                            {"p99_ms", t.p99_ms},
                            {"steps_above_tolerance", t.not_converged},
                            {"iterations", t.iterations},
                            {"linear_iterations", t.linear_iterations},
                            {"error_vs_converged", t.error_vs_converged}});
    j["notes"] = report.notes;
    write_file_atomically(dir / "bench.json", [&](std::ostream& out) { out << j.dump(2) << "\n"; });
    std::printf("wrote %s and bench.json\n", (dir / "bench.md").string().c_str());
  }
  return 0;
}

}  // namespace

Action add_bench_command(CLI::App& app) {
  auto o = std::make_shared<BenchCli>();
  CLI::App* cmd = app.add_subcommand("bench", "Dynamics benchmark: ms/step per integrator and mesh size");
  cmd->add_option("--sizes", o->sizes, "Cylinder sizes: 1k, 10k, 100k")->delimiter(',')->capture_default_str();
  cmd->add_option("--methods", o->options.methods,
                  "Calibration methods of the models, one row set each (default: any-nu-tet, stiffness-fit-volume; "
                  "with --all also lloyd-tet)")
      ->delimiter(',');
  cmd->add_option("--poisson", o->options.poisson, "Poisson's ratio of every model")->capture_default_str();
  cmd->add_option("--steps", o->options.steps, "Timed steps per integrator")->capture_default_str();
  cmd->add_option("--drag", o->options.drag,
                  "The probe's final offset along x, m (reached at half the run, then held; 0: no probe)")
      ->capture_default_str();
  cmd->add_option("--press", o->options.press,
                  "Instead of the drag, press the whole top down by this fraction of the height (e.g. 0.3)")
      ->capture_default_str();
  cmd->add_option(
         "--tool", o->options.tool_radius,
         "Instead of the drag, a rigid sphere of this radius (m) pressed into the top's centre through the "
         "contact barrier (docs/contact.md), by --tool-press x the height; with --haptics, the device presses it "
         "and the 1 kHz force comes from its local contact model")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--tool-press", o->options.tool_press, "With --tool: how far it presses, a fraction of the height")
      ->check(CLI::Range(0.0, 0.9))
      ->capture_default_str();
  add_settings(cmd, settings::describe(calibrate::model_settings(), settings::kBench), o->model);
  cmd->add_option("--integrators", o->options.integrators,
                  "Only these rows, e.g. \"quasi-newton (rest)\",\"local-global (chebyshev)\" (default: the "
                  "real-time path, quasi-newton (rest); with --all every row)")
      ->delimiter(',');
  cmd->add_flag("--all", o->all,
                "Every integrator's row for every default method (the full table; about 25 minutes on 2 cores for "
                "1k,10k) instead of the real-time path alone");
  cmd->add_option("-o,--out", o->out_dir, "Also write bench.md and bench.json here (haptics.md with --haptics)");
  cmd->add_flag("--haptics", o->haptics,
                "The multirate haptics benchmark instead: a 1 kHz haptic loop beside the deformation at its own "
                "rate, its rate and force against the drag simulated at 1 kHz throughout");
  cmd->add_option("--haptic-stiffness", o->haptic_stiffness,
                  "--haptics: the local model's stiffness: secant, condensed or none")
      ->capture_default_str();
  cmd->add_flag("--haptic-curvature,!--no-haptic-curvature", o->haptic_curvature,
                "--haptics: the local model's second-order term (the condensed energy's third derivative at the "
                "grab), or a model linear in the offset")
      ->capture_default_str();
  cmd->add_option("--deformation-dt", o->deformation_dt,
                  "--haptics: the deformation's step, s (0: measured, 1.25 x a step's wall time)")
      ->capture_default_str();
  cmd->add_option("--qn-hessian", o->qn_hessian,
                  "--haptics: the deformation's quasi-newton initial Hessian, rest or isotropic")
      ->capture_default_str();
  cmd->add_option("--qn-iterations", o->qn_iterations,
                  "--haptics: the deformation's (and the reference's) quasi-newton iterations per step at most (a "
                  "pressing tool's 10 ms steps on 11 425 nodes need about 20 to converge)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--qn-tolerance", o->qn_tolerance,
                  "--haptics: the deformation's (and the reference's) quasi-newton tolerance, in (0, 1)")
      ->capture_default_str();
  cmd->add_option("--ramp", o->ramp, "--haptics: the drag's smoothstep ramp, s")->capture_default_str();
  cmd->add_option("--hold", o->hold, "--haptics: the time it is held after the ramp, s")->capture_default_str();
  cmd->add_option("--reference-budget", o->reference_budget,
                  "--haptics: skip the full-rate reference when it would take longer than this, s")
      ->capture_default_str();
  return [o, cmd] {
    o->methods_given = cmd->count("--methods") > 0;
    o->rows_given = cmd->count("--integrators") > 0;
    return run_bench(*o);
  };
}

}  // namespace hooke::cli
