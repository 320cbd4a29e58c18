#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/quantile.hpp>
#include <hooke/experiments/dynamics_benchmark.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/model/load_case.hpp>
#include <hooke/solve/simulator.hpp>
#include <hooke/solve/tool_press.hpp>
#include <hooke/springs/spring_block.hpp>
#include <memory>
#include <sstream>

namespace hooke::experiments {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

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

mesh::Mesh benchmark_cylinder(int size) {
  if (size < 0 || size > 2) throw InvalidArgument("benchmark mesh sizes are 0, 1, 2 (1k, 10k, 100k nodes)");
  const int n[3] = {12, 24, 48}, layers[3] = {8, 24, 57};
  return mesh::tet_cylinder(0.01, 0.02, n[size], layers[size]);
}

calibrate::CalibratedModel benchmark_model(int size, const std::string& method, double poisson) {
  calibrate::ModelOptions o;
  o.method = method;
  o.density = 1000.0;
  return calibrate::calibrate_model(benchmark_cylinder(size), {material::Law::kLinear, 14630.0, poisson}, o);
}

std::vector<int> benchmark_probe_nodes(const mesh::Mesh& cylinder) {
  double top = -1e300, radius = 0.0;
  for (int i = 0; i < cylinder.node_count(); ++i) {
    top = std::max(top, cylinder.nodes(i, 2));
    radius = std::max(radius, std::hypot(cylinder.nodes(i, 0), cylinder.nodes(i, 1)));
  }
  std::vector<int> nodes;
  for (int i = 0; i < cylinder.node_count(); ++i)
    if (cylinder.nodes(i, 2) > top - 1e-9 * radius &&
        std::hypot(cylinder.nodes(i, 0), cylinder.nodes(i, 1)) <= 0.35 * radius)
      nodes.push_back(i);
  return nodes;
}

namespace {

struct Run {
  solve::Integrator integrator;
  solve::GlobalSolve global_solve;
  const char* name;
  solve::NewtonLinearSolver linear_solver = solve::NewtonLinearSolver::kCholesky;
  double cg_tolerance = 0.0;                                                     // 0: NewtonOptions' default (1e-6)
  solve::QuasiNewtonHessian initial_hessian = solve::QuasiNewtonHessian::kRest;  // quasi-newton
};
// local-global twice: with its prefactored direct global step and with the Chebyshev-Jacobi one.
constexpr Run kRuns[] = {
    {solve::Integrator::kSymplecticEuler, solve::GlobalSolve::kDirect, "symplectic-euler"},
    {solve::Integrator::kVelocityVerlet, solve::GlobalSolve::kDirect, "velocity-verlet"},
    {solve::Integrator::kImplicitEuler, solve::GlobalSolve::kDirect, "implicit-euler (cholesky)"},
    {solve::Integrator::kImplicitEuler, solve::GlobalSolve::kDirect, "implicit-euler (cg)",
     solve::NewtonLinearSolver::kConjugateGradient},
    {solve::Integrator::kImplicitEulerLinearised, solve::GlobalSolve::kDirect, "implicit-euler-linearised (cholesky)"},
    {solve::Integrator::kImplicitEulerLinearised, solve::GlobalSolve::kDirect, "implicit-euler-linearised (cg)",
     solve::NewtonLinearSolver::kConjugateGradient},
    // The same step with the linear solve stopped at 1e-2: the cheap end of the trade-off (docs/simulation.md).
    {solve::Integrator::kImplicitEulerLinearised, solve::GlobalSolve::kDirect, "implicit-euler-linearised (cg 1e-2)",
     solve::NewtonLinearSolver::kConjugateGradient, 1e-2},
    {solve::Integrator::kLocalGlobal, solve::GlobalSolve::kDirect, "local-global (direct)"},
    {solve::Integrator::kLocalGlobal, solve::GlobalSolve::kChebyshev, "local-global (chebyshev)"},
    // quasi-newton with its two initial Hessians (QuasiNewtonOptions' defaults otherwise).
    {solve::Integrator::kQuasiNewton, solve::GlobalSolve::kDirect, "quasi-newton (rest)"},
    {solve::Integrator::kQuasiNewton, solve::GlobalSolve::kDirect, "quasi-newton (isotropic)",
     solve::NewtonLinearSolver::kCholesky, 0.0, solve::QuasiNewtonHessian::kIsotropic},
    {solve::Integrator::kQuasiStatic, solve::GlobalSolve::kDirect, "quasi-static"}};

bool is_explicit(solve::Integrator i) {
  return i == solve::Integrator::kSymplecticEuler || i == solve::Integrator::kVelocityVerlet;
}

// Why the state after step k is not one a user could reach (empty when it is).
std::string inadmissible(const solve::Simulator& sim, const solve::StepReport& r, int k, bool budgeted) {
  if (!sim.positions().allFinite() || !sim.velocities().allFinite())
    return "step " + std::to_string(k) + " produced non-finite positions";
  if (!std::isfinite(sim.potential_energy())) return "step " + std::to_string(k) + " inverted an element";
  if (!r.converged && !budgeted) return "step " + std::to_string(k) + " ended above the Newton tolerance";
  return {};
}

// One row's run: an untimed first step, then `steps` timed ones, each checked (untimed) afterwards. `why` says
// where the run left the admissible set (empty when it did not); the timing is then incomplete.
StepTiming timed_run(solve::Simulator& sim, const Run& run, const BenchmarkDrag& drag, double dt, int steps,
                     std::string& why) {
  const bool budgeted = run.integrator == solve::Integrator::kQuasiNewton;
  drag.before_step(sim, dt);
  why = inadmissible(sim, sim.step(dt), 1, budgeted);
  std::vector<double> ms;
  StepTiming t;
  for (int k = 0; k < steps && why.empty(); ++k) {
    drag.before_step(sim, dt);
    const auto t0 = Clock::now();
    const solve::StepReport r = sim.step(dt);
    ms.push_back(ms_since(t0));
    t.iterations += r.iterations;
    t.linear_iterations += r.linear_iterations;
    t.not_converged += r.converged ? 0 : 1;
    why = inadmissible(sim, r, k + 2, budgeted);
  }
  if (!why.empty()) return t;
  t.integrator = run.name;
  t.dt = dt;
  t.median_ms = quantile(ms, 0.5);
  t.p95_ms = quantile(ms, 0.95);
  t.p99_ms = quantile(ms, 0.99);
  t.iterations /= steps;
  t.linear_iterations /= steps;
  return t;
}

SpringThroughput spring_throughput(const calibrate::CalibratedModel& cm, double triad) {
  const springs::SpringBlock springs(3, cm.springs.pairs, cm.springs.stiffness, cm.springs.rest_length);
  const VecX x = Eigen::Map<const VecX>(cm.mesh.nodes.data(), cm.mesh.nodes.size()) * 1.01;
  VecX g = VecX::Zero(x.size());
  std::vector<double> ms;
  for (int pass = 0; pass < 31; ++pass) {
    g.setZero();
    const auto t0 = Clock::now();
    springs.add_gradient(x, g);
    if (pass > 0) ms.push_back(ms_since(t0));
  }
  const double seconds = quantile(ms, 0.5) * 1e-3;
  const auto count = static_cast<double>(springs.pairs().size());
  return {cm.mesh.node_count(), static_cast<int>(count), seconds / count * 1e9,
          (24.0 * count + 72.0 * cm.mesh.node_count()) / seconds / triad};
}

}  // namespace

double BenchmarkDrag::offset(double t) const { return distance * std::min(1.0, t / ramp_s); }

void BenchmarkDrag::before_step(solve::Simulator& sim, double dt) const {
  if (tool) {
    solve::move_tool(sim, *contact, *tool, {tool_start + offset(sim.time() + dt) * direction, Mat3::Identity()});
    return;
  }
  if (nodes.empty()) return;
  solve::Probe p;
  p.nodes = nodes;
  p.offset = offset(sim.time() + dt) * direction;
  sim.set_probe(p);
}

VecX converged_reference(const model::Problem& problem, const solve::Dynamics& dynamics, double dt, int steps,
                         const BenchmarkDrag& probe) {
  solve::SimulatorOptions o;
  o.integrator = solve::Integrator::kImplicitEuler;
  o.newton.tolerance = 1e-12;
  o.newton.max_iterations = 200;
  solve::Simulator sim(problem, dynamics, o);
  for (int k = 0; k <= steps; ++k) {
    probe.before_step(sim, dt);
    sim.step(dt);
  }
  return sim.positions();
}

double relative_error(const VecX& x, const VecX& reference, const VecX& rest) {
  double error = 0.0, scale = 0.0;
  for (Eigen::Index i = 0; i < x.size() / 3; ++i) {
    error = std::max(error, (x.segment<3>(3 * i) - reference.segment<3>(3 * i)).norm());
    scale = std::max(scale, (reference.segment<3>(3 * i) - rest.segment<3>(3 * i)).norm());
  }
  return scale > 0.0 ? error / scale : 0.0;
}

DynamicsBenchmarkReport run_dynamics_benchmark(const DynamicsBenchmarkOptions& options) {
  if (options.steps < 1) throw InvalidArgument("the benchmark needs at least one step per integrator");
  for (int size : options.sizes) benchmark_cylinder(size);  // refuse a bad size before measuring anything
  for (const std::string& name : options.integrators)
    if (std::none_of(std::begin(kRuns), std::end(kRuns), [&](const Run& r) { return name == r.name; }))
      throw InvalidArgument("the benchmark has no row '" + name + "'");
  DynamicsBenchmarkReport report;
  const auto begin = Clock::now();
  auto progress = [&](const std::string& what) {
    if (!options.progress) return;
    char elapsed[32];
    std::snprintf(elapsed, sizeof elapsed, " (%.0f s)", 1e-3 * ms_since(begin));
    options.progress(what + elapsed);
  };
  const double triad = triad_bytes_per_second();
  report.triad_gbps = triad * 1e-9;
  for (int size : options.sizes) {
    bool first_method = true;
    for (const std::string& method : options.methods) {
      calibrate::CalibratedModel cm = benchmark_model(size, method, options.poisson);
      cm.springs.spring_exponent = options.spring_exponent;
      cm.springs.volume_exponent = options.volume_exponent;
      const int nodes = cm.mesh.node_count();
      progress(std::to_string(nodes) + " nodes, " + method + ": calibrated");
      if (first_method) report.springs.push_back(spring_throughput(cm, triad));
      first_method = false;
      const calibrate::BuiltModel built = calibrate::build_model(cm);
      const model::LoadCase supports = model::make_load_case(cm.mesh, model::LoadKind::kStretch, 0.0);
      BenchmarkDrag drag;
      const double ramp = 0.5 * (options.steps + 1) * options.dt;
      if (options.tool_radius > 0.0) {  // a sphere touching the top's centre, pressed down
        const double top = cm.mesh.nodes.col(2).maxCoeff();
        drag.tool = std::make_shared<contact::RigidTool>(contact::ToolShape::kSphere, options.tool_radius);
        drag.tool_start = Vec3(0.0, 0.0, top + options.tool_radius);
        drag.tool->set_pose({drag.tool_start, Mat3::Identity()});
        auto block = contact::boundary_contact(cm.mesh, cm.material.youngs_modulus, drag.tool);
        drag.contact = block.get();
        built.model->add(std::move(block));
        drag.distance = options.tool_press * supports.height;
        drag.ramp_s = ramp;
        drag.direction = -Vec3::UnitZ();
      }
      model::Problem problem = model::make_problem(built.model);
      model::fix_nodes(problem, supports.fixed_nodes);
      const solve::Dynamics dynamics{cm.masses, Vec3(0.0, 0.0, -9.81), 0.0, 0.0};
      if (!drag.tool && options.press > 0.0)
        drag = {supports.top_nodes, options.press * supports.height, ramp, -Vec3::UnitZ(), nullptr, nullptr,
                Vec3::Zero()};
      else if (!drag.tool && options.drag != 0.0)
        drag = {benchmark_probe_nodes(cm.mesh), options.drag, ramp, Vec3::UnitX(), nullptr, nullptr, Vec3::Zero()};
      VecX reference;
      for (const Run& run : kRuns) {
        if (!options.integrators.empty() &&
            std::find(options.integrators.begin(), options.integrators.end(), run.name) == options.integrators.end())
          continue;
        const std::string on = " on " + std::to_string(nodes) + " nodes (" + method + ")";
        const bool factorises = run.linear_solver == solve::NewtonLinearSolver::kCholesky &&
                                (run.integrator == solve::Integrator::kImplicitEuler ||
                                 run.integrator == solve::Integrator::kImplicitEulerLinearised ||
                                 run.integrator == solve::Integrator::kQuasiStatic);
        const bool newton =
            run.integrator == solve::Integrator::kImplicitEuler || run.integrator == solve::Integrator::kQuasiStatic;
        if ((factorises || newton) && size == 2) {
          report.notes.push_back(
              std::string(run.name) + " skipped" + on +
              (factorises
                   ? " (a sparse factorisation of " + std::to_string(3 * nodes) + " DOFs per Newton iteration)"
                   : " (several Newton iterations of " + std::to_string(3 * nodes) + "-DOF CG solves per step)"));
          continue;
        }
        solve::SimulatorOptions o;
        o.integrator = run.integrator;
        o.global_solve = run.global_solve;
        o.newton.linear_solver = run.linear_solver;
        if (run.cg_tolerance > 0.0) o.newton.cg_tolerance = run.cg_tolerance;
        o.quasi_newton.initial_hessian = run.initial_hessian;
        std::unique_ptr<solve::Simulator> sim;
        try {
          sim = std::make_unique<solve::Simulator>(problem, dynamics, o);
        } catch (const InvalidArgument& e) {  // local-global on a model with volume terms
          report.notes.push_back(std::string(run.name) + on + " not applicable: " + e.what());
          continue;
        }
        const double dt = is_explicit(run.integrator) ? 0.9 * sim->stable_time_step() : options.dt;
        std::string why;
        StepTiming t = timed_run(*sim, run, drag, dt, options.steps, why);
        if (!why.empty()) {
          report.notes.push_back(std::string(run.name) + on + " not reported: " + why);
          progress(report.notes.back());
          continue;
        }
        t.nodes = nodes;
        t.method = method;
        if (!is_explicit(run.integrator) && run.integrator != solve::Integrator::kQuasiStatic && size < 2) {
          if (drag.tool) t.tool_force = drag.contact->tool_force(sim->positions()).dot(-drag.direction);
          if (reference.size() == 0) {
            reference = converged_reference(problem, dynamics, options.dt, options.steps, drag);
            progress(std::to_string(nodes) + " nodes, " + method + ": converged reference (" +
                     std::to_string(options.steps + 1) + " implicit-Euler steps, Newton to 1e-12)");
          }
          t.error_vs_converged = relative_error(sim->positions(), reference, problem.model->rest_positions());
          if (drag.tool) {
            drag.tool->set_pose(
                {drag.tool_start + drag.offset((options.steps + 1) * options.dt) * drag.direction, Mat3::Identity()});
            t.reference_tool_force = drag.contact->tool_force(reference).dot(-drag.direction);
          }
        }
        report.steps.push_back(t);
        char row[200];
        std::snprintf(row, sizeof row, "%d nodes, %s, %s: %.3f ms median, p99 %.3f ms, %d steps above tolerance", nodes,
                      method.c_str(), run.name, t.median_ms, t.p99_ms, t.not_converged);
        std::string line = row;
        if (t.error_vs_converged >= 0.0) {
          std::snprintf(row, sizeof row, ", error %.2g of a converged step", t.error_vs_converged);
          line += row;
        }
        progress(line);
      }
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
  s << "\n| nodes | model | integrator | dt (ms) | ms/step median | p95 | p99 | iterations/step | CG iterations/step | "
       "steps above tolerance | error vs converged |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& t : report.steps) {
    char error[32] = "-";
    if (t.error_vs_converged >= 0.0) std::snprintf(error, sizeof error, "%.2g", t.error_vs_converged);
    std::snprintf(line, sizeof line, "| %d | %s | %s | %.3g | %.3f | %.3f | %.3f | %.2f | %.1f | %d | %s |\n", t.nodes,
                  t.method.c_str(), t.integrator.c_str(), 1e3 * t.dt, t.median_ms, t.p95_ms, t.p99_ms, t.iterations,
                  t.linear_iterations, t.not_converged, error);
    s << line;
  }
  s << "\nerror vs converged: max node distance to implicit Euler with Newton to 1e-12 after the same steps (gravity "
       "and the probe's drag), over its largest displacement (same dt; - where the integrator solves another "
       "problem).\n";
  bool tool = false;
  for (const auto& t : report.steps) tool = tool || t.reference_tool_force != 0.0;
  if (tool) {
    s << "\nThe force on the pressing sphere after the last step against the converged reference's:\n\n| nodes | model "
         "| "
         "integrator | force (N) | reference (N) | relative difference |\n|---|---|---|---|---|---|\n";
    for (const auto& t : report.steps) {
      if (t.reference_tool_force == 0.0) continue;
      std::snprintf(line, sizeof line, "| %d | %s | %s | %.6g | %.6g | %.2g |\n", t.nodes, t.method.c_str(),
                    t.integrator.c_str(), t.tool_force, t.reference_tool_force,
                    std::abs(t.tool_force - t.reference_tool_force) / std::abs(t.reference_tool_force));
      s << line;
    }
  }
  for (const auto& n : report.notes) s << "\n- " << n;
  if (!report.notes.empty()) s << "\n";
  return s.str();
}

}  // namespace hooke::experiments
