// Identification of the benchmark cylinders (experiments::benchmark_cylinder: 1 089, 11 425 and 103 066 nodes; E
// 14 630 Pa, nu 0.45, linear FEM reference) from the 12 training load cases of experiments::fem_reference_cases
// (issue 15: the 100k-node cylinder in at most 2 minutes and 6 GB on 2 cores):
// - BM_IdentifyReference: the 12 FEM reference solves (three factorisations, four right-hand sides each);
// - BM_IdentifyForces: Lloyd's Eq. 2 for springs+volume (k per edge, k_V per tet) by bounded least squares, as
//   `hooke identify` runs it: started from the any-nu-tet model (calibrated inside the timed loop) at relative
//   tolerance 1e-2 (`--tolerance 1e-2`). On the 11k cylinder the force residual is then 0.2606 against 0.2600 at
//   1e-4, which takes 11x the iterations: the objective settles long before the single parameters do.
// Counters: unknowns, CG iterations, the relative force residual, and the process's peak resident memory (MB, the
// high-water mark of the whole run so far, so the reference's factorisations included).
// Run: build/release/bench/hooke_bench --benchmark_filter=Identify (studies of the solver: HOOKE_LSQ_TOL, HOOKE_REG,
// HOOKE_CG, HOOKE_GP set the tolerance, --regularize, CG iterations and projected-gradient steps per outer iteration;
// HOOKE_START the analytic start method, or none)
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <fstream>
#include <hooke/calibrate/method.hpp>
#include <hooke/experiments/dynamics_benchmark.hpp>
#include <hooke/experiments/identification.hpp>
#include <string>

#include "bench_common.hpp"

namespace {

using namespace hooke;

const material::Material kTissue{material::Law::kLinear, 14630.0, 0.45};

double peak_rss_mb() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // kB
  return 0.0;
}

struct Reference {
  mesh::Mesh mesh;
  std::vector<identify::ReferenceCase> cases;
  explicit Reference(int size) : mesh(experiments::benchmark_cylinder(size)) {
    experiments::ReferenceLoads loads;
    loads.held_out = 0;
    cases = experiments::fem_reference_cases(mesh, kTissue, loads);
  }
};

void BM_IdentifyReference(benchmark::State& state) {
  const mesh::Mesh mesh = experiments::benchmark_cylinder(static_cast<int>(state.range(0)));
  experiments::ReferenceLoads loads;
  loads.held_out = 0;
  for (auto _ : state) benchmark::DoNotOptimize(experiments::fem_reference_cases(mesh, kTissue, loads).size());
  state.counters["nodes"] = mesh.node_count();
  state.counters["peak_rss_mb"] = peak_rss_mb();
}
BENCHMARK(BM_IdentifyReference)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_IdentifyForces(benchmark::State& state) {
  const Reference& r = bench::cached<Reference>(static_cast<int>(state.range(0)));
  identify::IdentifyOptions options;
  options.objective = identify::Objective::kForces;
  options.parameters = identify::Parameters::kSpringsVolume;
  options.least_squares.tolerance = 1e-2;  // residual within 0.3 % of its minimum (header)
  if (const char* t = std::getenv("HOOKE_LSQ_TOL")) options.least_squares.tolerance = std::atof(t);
  if (const char* w = std::getenv("HOOKE_REG")) options.regularization = std::atof(w);
  if (const char* c = std::getenv("HOOKE_CG")) options.least_squares.max_cg_iterations = std::atoi(c);
  if (const char* g = std::getenv("HOOKE_GP")) options.least_squares.projected_gradient_steps = std::atoi(g);
  const char* start = std::getenv("HOOKE_START");
  const std::string method = start ? start : "any-nu-tet";
  identify::Identification id;
  for (auto _ : state) {
    if (method != "none")
      options.start_model = calibrate::calibrate(r.mesh, {kTissue}, calibrate::method_from_name(method));
    id = identify::identify(r.mesh, r.cases, options);
  }
  state.counters["nodes"] = r.mesh.node_count();
  state.counters["unknowns"] = id.layout.size();
  state.counters["cg_iterations"] = static_cast<double>(id.report.least_squares.cg_iterations);
  state.counters["force_residual"] = id.report.force_residual;
  state.counters["converged"] = id.report.least_squares.converged;
  state.counters["outer"] = id.report.least_squares.iterations;
  state.counters["peak_rss_mb"] = peak_rss_mb();
}
BENCHMARK(BM_IdentifyForces)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
