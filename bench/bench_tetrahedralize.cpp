// Tetrahedralizing real scans (CGAL's femur, 3 897 nodes, and the Stanford bunny, 37 706 nodes; Debian
// libcgal-demo) with the surface kept, at 0, 1 and 3 Netgen optimisation passes and with TetGen's program: seconds
// beside the mesh's size and quality (min radius ratio, smallest dihedral, slivers below 0.01), so that a faster
// setting or mesher is seen with what it costs. Run:
//   build/release/bench/hooke_bench --benchmark_filter=Tetrahedralize
#include <benchmark/benchmark.h>

#include <filesystem>
#include <hooke/io/mesh_io.hpp>
#include <hooke/io/mesher.hpp>
#include <string>

namespace {

using namespace hooke;

const char* kScans[] = {"femur.off", "bunny00.off"};

void run(benchmark::State& state, const mesh::TetrahedralizeOptions& o) {
  const std::filesystem::path path = std::filesystem::path(HOOKE_SCAN_DATA) / kScans[state.range(0)];
  if (!std::filesystem::exists(path)) {
    state.SkipWithError((path.string() + " is missing: scripts/setup.sh installs libcgal-demo").c_str());
    return;
  }
  const mesh::Mesh surface = io::read_mesh(path);
  mesh::TetrahedralizeReport r;
  for (auto _ : state) benchmark::DoNotOptimize(io::tetrahedralize(surface, o, &r));
  state.SetLabel(kScans[state.range(0)]);
  state.counters["surface_nodes"] = r.surface_nodes;
  state.counters["tets"] = r.tets;
  state.counters["min_radius_ratio"] = r.quality.min_radius_ratio;
  state.counters["mean_radius_ratio"] = r.quality.mean_radius_ratio;
  state.counters["min_dihedral_deg"] = r.quality.min_dihedral;
  state.counters["slivers"] = r.slivers;
}

void BM_Tetrahedralize(benchmark::State& state) {
  mesh::TetrahedralizeOptions o;
  o.optimisation_steps = static_cast<int>(state.range(1));
  run(state, o);
}
BENCHMARK(BM_Tetrahedralize)
    ->ArgsProduct({{0, 1}, {0, 1, 3}})
    ->ArgNames({"scan", "opt"})
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->ReportAggregatesOnly(true);

void BM_TetrahedralizeTetgen(benchmark::State& state) {
  mesh::TetrahedralizeOptions o;
  o.mesher = mesh::Mesher::kTetgen;
  run(state, o);
}
BENCHMARK(BM_TetrahedralizeTetgen)
    ->DenseRange(0, 1)
    ->ArgName("scan")
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->ReportAggregatesOnly(true);

}  // namespace
