#include <algorithm>
#include <chrono>
#include <cstdio>
#include <hooke/calibrate/method.hpp>
#include <hooke/core/error.hpp>
#include <hooke/experiments/dynamics_benchmark.hpp>
#include <hooke/experiments/load_case.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/model/mass.hpp>
#include <hooke/solve/simulator.hpp>
#include <hooke/springs/spring_block.hpp>
#include <sstream>

namespace hooke::experiments {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(q * static_cast<double>(v.size() - 1) + 0.5)];
}

// Best of 5 passes of a[i] = b[i] + 3 c[i] over 3 x 16 M doubles on all threads (STREAM's byte count).
double triad_bytes_per_second() {
  const size_t n = size_t(1) << 24;
  std::vector<double> a(n), b(n), c(n);
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < n; ++i) {
    a[i] = 0.0;
    b[i] = 1.0;
    c[i] = 2.0;
  }
  double best = 1e300;
  for (int pass = 0; pass < 5; ++pass) {
    const auto t0 = Clock::now();
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; ++i) a[i] = b[i] + 3.0 * c[i];
    best = std::min(best, ms_since(t0) * 1e-3);
  }
  if (a[n / 2] != 7.0) throw InvalidArgument("triad: wrong result");  // keeps the loop from being dropped
  return 3.0 * static_cast<double>(n * sizeof(double)) / best;
}

}  // namespace

DynamicsBenchmarkReport run_dynamics_benchmark(const DynamicsBenchmarkOptions& options) {
  if (options.steps < 1) throw InvalidArgument("the benchmark needs at least one step per integrator");
  DynamicsBenchmarkReport report;
  const double triad = triad_bytes_per_second();
  report.triad_gbps = triad * 1e-9;
  for (int size : options.sizes) {
    if (size < 0 || size > 2) throw InvalidArgument("benchmark mesh sizes are 0, 1, 2 (1k, 10k, 100k nodes)");
    const int n[3] = {10, 20, 44}, layers[3] = {8, 24, 50};
    const mesh::Mesh m = mesh::tet_cylinder(0.01, 0.02, n[size], layers[size]);
    auto model = calibrate::make_model(
        m, calibrate::calibrate(m, {{material::Law::kLinear, 14630.0, 0.25}}, calibrate::Method::kLloydTet));
    const springs::SpringBlock* springs = nullptr;
    for (const auto& b : model->blocks())
      if (const auto* s = dynamic_cast<const springs::SpringBlock*>(b.get())) springs = s;
    {
      const VecX x = model->rest_positions() * 1.01;
      VecX g = VecX::Zero(x.size());
      std::vector<double> ms;
      for (int pass = 0; pass < 31; ++pass) {
        g.setZero();
        const auto t0 = Clock::now();
        springs->add_gradient(x, g);
        if (pass > 0) ms.push_back(ms_since(t0));
      }
      const double seconds = quantile(ms, 0.5) * 1e-3;
      const auto count = static_cast<double>(springs->pairs().size());
      report.springs.push_back({m.node_count(), static_cast<int>(count), seconds / count * 1e9,
                                (24.0 * count + 72.0 * m.node_count()) / seconds / triad});
    }
    model::Problem problem = model::make_problem(model);
    model::fix_nodes(problem, make_load_case(m, LoadKind::kStretch, 0.0).fixed_nodes);
    VecX gravity = VecX::Zero(3);
    gravity(2) = -9.81;
    const solve::Dynamics dynamics{model::lumped_masses(m, 1000.0), gravity, 0.0, 0.0};
    // local-global twice: with its prefactored direct global step and with the Chebyshev-Jacobi one.
    const std::pair<solve::Integrator, solve::GlobalSolve> runs[] = {
        {solve::Integrator::kSymplecticEuler, solve::GlobalSolve::kDirect},
        {solve::Integrator::kVelocityVerlet, solve::GlobalSolve::kDirect},
        {solve::Integrator::kImplicitEuler, solve::GlobalSolve::kDirect},
        {solve::Integrator::kLocalGlobal, solve::GlobalSolve::kDirect},
        {solve::Integrator::kLocalGlobal, solve::GlobalSolve::kChebyshev},
        {solve::Integrator::kQuasiStatic, solve::GlobalSolve::kDirect}};
    for (const auto& [integrator, global_solve] : runs) {
      std::string name(solve::integrator_name(integrator));
      if (integrator == solve::Integrator::kLocalGlobal)
        name += global_solve == solve::GlobalSolve::kChebyshev ? " (chebyshev)" : " (direct)";
      const bool newton =
          integrator == solve::Integrator::kImplicitEuler || integrator == solve::Integrator::kQuasiStatic;
      if (newton && size == 2) {
        report.notes.push_back(name + " skipped on " + std::to_string(m.node_count()) +
                               " nodes (a sparse factorisation of " + std::to_string(3 * m.node_count()) +
                               " DOFs per Newton matrix)");
        continue;
      }
      solve::SimulatorOptions o;
      o.integrator = integrator;
      o.global_solve = global_solve;
      solve::Simulator sim(problem, dynamics, o);
      const bool explicit_step =
          integrator == solve::Integrator::kSymplecticEuler || integrator == solve::Integrator::kVelocityVerlet;
      const double dt = explicit_step ? 0.9 * sim.stable_time_step() : options.dt;
      sim.step(dt);
      std::vector<double> ms;
      double iterations = 0.0;
      for (int k = 0; k < options.steps; ++k) {
        const auto t0 = Clock::now();
        iterations += sim.step(dt).iterations;
        ms.push_back(ms_since(t0));
      }
      report.steps.push_back(
          {m.node_count(), name, dt, quantile(ms, 0.5), quantile(ms, 0.95), iterations / options.steps});
    }
  }
  return report;
}

std::string dynamics_benchmark_markdown(const DynamicsBenchmarkReport& report) {
  std::ostringstream s;
  char line[256];
  std::snprintf(line, sizeof line, "Triad bandwidth (all threads): %.1f GB/s\n\n", report.triad_gbps);
  s << line << "| nodes | springs | ns/spring | fraction of triad bandwidth |\n|---|---|---|---|\n";
  for (const auto& t : report.springs) {
    std::snprintf(line, sizeof line, "| %d | %d | %.2f | %.2f |\n", t.nodes, t.springs, t.ns_per_spring,
                  t.bandwidth_fraction);
    s << line;
  }
  s << "\n| nodes | integrator | dt (ms) | ms/step median | ms/step p95 | iterations/step "
       "|\n|---|---|---|---|---|---|\n";
  for (const auto& t : report.steps) {
    std::snprintf(line, sizeof line, "| %d | %s | %.3g | %.3f | %.3f | %.2f |\n", t.nodes, t.integrator.c_str(),
                  1e3 * t.dt, t.median_ms, t.p95_ms, t.iterations);
    s << line;
  }
  for (const auto& n : report.notes) s << "\n- " << n;
  if (!report.notes.empty()) s << "\n";
  return s.str();
}

}  // namespace hooke::experiments
