#pragma once
/// The dynamics benchmark behind `hooke bench` (bench/bench_dynamics.cpp measures the same with Google
/// Benchmark, and adds Bullet): tetrahedral cylinders of about 1 000, 10 000 and 100 000 nodes (benchmark_cylinder,
/// r 1 cm, h 2 cm, lloyd-tet springs for E 14 630 Pa, nu 0.25, 1 000 kg/m^3, bottom clamped, gravity).
#include <hooke/calibrate/calibrated_model.hpp>
#include <hooke/core/types.hpp>
#include <string>
#include <vector>

namespace hooke::experiments {

/// The benchmark's cylinder of size 0, 1, 2: mesh::tet_cylinder(0.01, 0.02, n, layers) with (n, layers) = (12, 8),
/// (24, 24), (48, 57): 1 089, 11 425 and 103 066 nodes, minimum tet quality 0.29-0.34.
/// @throws InvalidArgument for another size
mesh::Mesh benchmark_cylinder(int size);

/// Its model: lloyd-tet springs for E 14 630 Pa, nu 0.25 and lumped masses of 1 000 kg/m^3.
calibrate::CalibratedModel benchmark_model(int size);

struct DynamicsBenchmarkOptions {
  std::vector<int> sizes = {0, 1};  ///< 0, 1, 2: the 1 089-, 11 425- and 103 066-node cylinders
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
  double iterations = 0.0;         ///< solver iterations per step
  double linear_iterations = 0.0;  ///< conjugate-gradient iterations per step (cg rows; 0 otherwise)
  /// Max node distance to implicit Euler converged tightly (Newton to 1e-12) after the same steps, relative to its
  /// largest displacement; -1 where the integrator solves another problem (explicit steps, quasi-static).
  double error_vs_converged = -1.0;
};

struct DynamicsBenchmarkReport {
  double triad_gbps = 0.0;  ///< STREAM-like triad on all threads, GB/s, measured first
  std::vector<SpringThroughput> springs;
  std::vector<StepTiming> steps;
  std::vector<std::string> notes;  ///< what was skipped and why
};

/// Runs the benchmark: triad, spring forces (median of 30 passes), then every integrator per mesh (implicit-euler
/// and quasi-static only up to the 11 425-node mesh: their Newton matrices need a fresh factorisation of 310 000
/// DOFs on the largest one). Every timed run is checked after each step (untimed): a run that leaves the
/// admissible set (an inverted element, a non-finite position) or ends a step above its Newton tolerance is not
/// reported; a note says which and where.
/// @throws InvalidArgument on a size outside 0..2 or steps < 1
DynamicsBenchmarkReport run_dynamics_benchmark(const DynamicsBenchmarkOptions& options);

/// The report as Markdown tables.
std::string dynamics_benchmark_markdown(const DynamicsBenchmarkReport& report);

}  // namespace hooke::experiments
