#pragma once
/// The dynamics benchmark behind `hooke bench` (bench/bench_dynamics.cpp measures the same with Google
/// Benchmark, and adds Bullet): tetrahedral cylinders of about 1 000, 10 000 and 100 000 nodes (mesh::tet_cylinder,
/// r 1 cm, h 2 cm, lloyd-tet springs for E 14 630 Pa, nu 0.25, 1 000 kg/m^3, bottom clamped, gravity).
#include <hooke/core/types.hpp>
#include <string>
#include <vector>

namespace hooke::experiments {

struct DynamicsBenchmarkOptions {
  std::vector<int> sizes = {0, 1};  ///< 0, 1, 2: the 1 089-, 11 025- and 103 275-node cylinders
  int steps = 40;                   ///< timed steps per integrator (after one untimed first step)
  double dt = 1e-3;                 ///< implicit step, s; explicit integrators run at 0.9 x their stability limit
};

/// Spring-force throughput on one mesh beside the in-run bandwidth bound.
struct SpringThroughput {
  int nodes = 0, springs = 0;
  double ns_per_spring = 0.0;       ///< median pass time / springs
  double bandwidth_fraction = 0.0;  ///< (24 B per spring + 72 B per node) / pass time / triad bandwidth
};

/// ms per step of one integrator on one mesh.
struct StepTiming {
  int nodes = 0;
  std::string integrator;
  double dt = 0.0;  ///< s
  double median_ms = 0.0, p95_ms = 0.0;
  double iterations = 0.0;  ///< solver iterations per step
};

struct DynamicsBenchmarkReport {
  double triad_gbps = 0.0;  ///< STREAM-like triad on all threads, GB/s, measured first
  std::vector<SpringThroughput> springs;
  std::vector<StepTiming> steps;
  std::vector<std::string> notes;  ///< what was skipped and why
};

/// Runs the benchmark: triad, spring forces (median of 30 passes), then every integrator per mesh (implicit-euler
/// and quasi-static only up to the 11 025-node mesh: their Newton matrices need a fresh factorisation of 310 000
/// DOFs on the largest one).
/// @throws InvalidArgument on a size outside 0..2 or steps < 1
DynamicsBenchmarkReport run_dynamics_benchmark(const DynamicsBenchmarkOptions& options);

/// The report as Markdown tables.
std::string dynamics_benchmark_markdown(const DynamicsBenchmarkReport& report);

}  // namespace hooke::experiments
