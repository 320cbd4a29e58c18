// Linear FEM reference on tetrahedral boxes up to ~100 000 nodes: assembly of K, sparse factorisation
// (CHOLMOD supernodal), solve, and peak resident memory; beside a STREAM-like triad measured in the same
// run as the machine's memory-bandwidth baseline. Run: build/release/bench/hooke_bench
//   --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <chrono>

#include <hooke/core/sparse_cholesky.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/model/free_map.hpp>
#include <hooke/model/load_case.hpp>
#include <hooke/model/problem.hpp>
#include <memory>

#include "bench_common.hpp"

namespace {

using namespace hooke;

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;  // Linux reports KiB
}

// Box of n x n x (n + 3) cubes, 6 tets each: n = 45 gives 46 * 46 * 49 = 103 684 nodes.
struct Setup {
  mesh::Mesh mesh;
  std::shared_ptr<model::Model> model;
  model::Problem problem;
  explicit Setup(int n) {
    mesh = mesh::tet_box(0.02, 0.02, 0.02 * (n + 3) / n, n, n, n + 3);
    model = std::make_shared<model::Model>(3, Eigen::Map<const VecX>(mesh.nodes.data(), mesh.nodes.size()));
    model->add(fem::make_elastic_block(mesh, {material::Law::kLinear, 14630.0, 0.3}));
    problem = model::make_problem(model);
    model::apply(model::make_load_case(mesh, model::LoadKind::kStretch, 1000.0), problem);
  }
};

void BM_Assembly(benchmark::State& state) {
  Setup& s = bench::cached<Setup>(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    SparseMatrix k = s.model->hessian(s.model->rest_positions());
    benchmark::DoNotOptimize(k.valuePtr());
  }
  state.counters["nodes"] = s.mesh.node_count();
  state.counters["tets"] = s.mesh.element_count();
  state.counters["ns_per_tet"] =
      benchmark::Counter(static_cast<double>(s.mesh.element_count()),
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["peak_rss_MB"] = peak_rss_mb();
}

void BM_Factorization(benchmark::State& state) {
  Setup& s = bench::cached<Setup>(static_cast<int>(state.range(0)));
  const model::FreeMap map(model::free_dofs(s.problem), s.model->dof_count());
  const SparseMatrix k = map.restrict(s.model->hessian(s.model->rest_positions()));
  const VecX f = map.restrict(s.problem.external_force);
  double solve_seconds = 0.0;
  for (auto _ : state) {
    SparseCholesky chol;
    if (!chol.factorize(k)) state.SkipWithError("factorisation failed");
    state.PauseTiming();
    const auto t0 = std::chrono::steady_clock::now();
    const VecX u = chol.solve(f);
    solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    benchmark::DoNotOptimize(u.data());
    state.ResumeTiming();
  }
  state.counters["dofs"] = static_cast<double>(k.rows());
  state.counters["solve_ms"] = 1e3 * solve_seconds;
  state.counters["peak_rss_MB"] = peak_rss_mb();
}

void BM_StreamTriad(benchmark::State& state) { bench::run_triad(state); }

}  // namespace

// Sizes grow and the triad runs last, so each peak_rss_MB is the peak of the pipeline up to that size.
BENCHMARK(BM_Assembly)->Arg(10)->Arg(21)->Arg(45)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_Factorization)->Arg(10)->Arg(21)->Arg(45)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_StreamTriad)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
