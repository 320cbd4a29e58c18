// Dynamics on tetrahedral cylinders (r 1 cm, h 2 cm; mesh::tet_cylinder) of about 1 000, 11 000 and 103 000
// nodes with lloyd-tet springs (E 14 630 Pa, nu 0.25, 1 000 kg/m^3), bottom clamped, gravity:
// - spring-force evaluation throughput (ns/spring) and its fraction of the memory-bandwidth bound, against a
//   STREAM-like triad measured first in the same run;
// - ms/step of each integrator: implicit ones at dt = 1 ms, explicit ones at 0.9 x their stability limit
//   (dt = 1 ms is beyond it on these meshes; the counter dt_ms says which).
// Run: build/release/bench/hooke_bench --benchmark_filter='Triad|Spring|Step'
#include <benchmark/benchmark.h>

#include <string>

#include "bench_common.hpp"
#include "bench_cylinder.hpp"

namespace {

using namespace hooke;

using bench::Cylinder;

void BM_DynTriad(benchmark::State& state) { bench::run_triad(state); }

// Bytes a spring-force pass must move at least: per spring its two indices, k and l0 (24 B), and per node its
// position read and its gradient read and written once (72 B), when every node stays in cache between the
// springs that share it (a banded node order makes this nearly so).
void BM_SpringForces(benchmark::State& state) {
  Cylinder& c = bench::cached<Cylinder>(static_cast<int>(state.range(0)));
  const VecX x = c.model->rest_positions() * 1.01;
  VecX g = VecX::Zero(x.size());
  for (auto _ : state) {
    g.setZero();
    c.springs->add_gradient(x, g);
    benchmark::DoNotOptimize(g.data());
  }
  const double springs = static_cast<double>(c.springs->pairs().size());
  const double bytes = 24.0 * springs + 72.0 * c.mesh.node_count();
  state.counters["nodes"] = c.mesh.node_count();
  state.counters["springs"] = springs;
  state.counters["ns_per_spring"] =
      benchmark::Counter(springs, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["GBps"] = benchmark::Counter(bytes / 1e9, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["fraction_of_triad"] = benchmark::Counter(bytes / std::max(bench::triad_bytes_per_second(), 1.0),
                                                           benchmark::Counter::kIsIterationInvariantRate);
}

// One energy-and-gradient pass of the 1 089-node any-nu-tet model (springs, volume terms, orientation guard) under
// the large-strain term laws (docs/methods/large_strain.md): Hookean / quadratic (1, 1), log springs with barrier
// volumes (0, -2), and a law off the integer grid (0.125, -1.5), at a 5 % compression-like state.
void BM_TermLawForces(benchmark::State& state) {
  static const calibrate::CalibratedModel base = experiments::benchmark_model(0, "any-nu-tet", 0.45);
  calibrate::CalibratedModel cm = base;
  cm.springs.spring_exponent = static_cast<double>(state.range(0)) / 8.0;
  cm.springs.volume_exponent = static_cast<double>(state.range(1)) / 8.0;
  const auto model = calibrate::build_model(cm).model;
  VecX x = model->rest_positions();
  for (Eigen::Index i = 2; i < x.size(); i += 3) x(i) *= 0.95;
  VecX g = VecX::Zero(x.size());
  for (auto _ : state) {
    g.setZero();
    benchmark::DoNotOptimize(model->energy_and_gradient(x, g));
  }
  state.SetLabel("m " + std::to_string(cm.springs.spring_exponent) + ", q " +
                 std::to_string(cm.springs.volume_exponent));
}

void BM_Step(benchmark::State& state) {
  Cylinder& c = bench::cached<Cylinder>(static_cast<int>(state.range(0)));
  const auto integrator = static_cast<solve::Integrator>(state.range(1));
  solve::SimulatorOptions o;
  o.integrator = integrator;
  solve::Simulator sim(c.problem, c.dynamics, o);
  const bool explicit_step =
      integrator == solve::Integrator::kSymplecticEuler || integrator == solve::Integrator::kVelocityVerlet;
  const double dt = explicit_step ? 0.9 * sim.stable_time_step() : 1e-3;
  sim.step(dt);  // first step: symbolic analysis, factorisations
  for (auto _ : state) benchmark::DoNotOptimize(sim.step(dt).iterations);
  state.SetLabel(std::string(solve::integrator_name(integrator)));
  state.counters["nodes"] = c.mesh.node_count();
  state.counters["dt_ms"] = 1e3 * dt;
}

}  // namespace

BENCHMARK(BM_DynTriad)->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK(BM_SpringForces)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TermLawForces)->Args({8, 8})->Args({0, -16})->Args({1, -12})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Step)
    ->ArgsProduct({{0, 1}, {0, 1, 2, 3, 4, 5}})
    ->Args({2, 0})
    ->Args({2, 3})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0);
