// Peer comparison with VegaFEM's implicit backward Euler (Barbič et al., github.com/dyollb/VegaFEM, built outside
// this tree by scripts/build_vegafem.sh from a fetched copy; nothing of it is committed), in the same run and on
// the same cylinders as `hooke bench`: experiments::benchmark_cylinder, E 14 630 Pa, nu 0.45, 1 000 kg/m^3, bottom
// clamped, gravity, dt = 1 ms, no damping, 300 steps after an untimed first one, and the same probe: the top's
// centre held and dragged 2 mm along x, linearly until half the run's simulated time, then held.
// - Vega: StVK tets (StVKForceModel), hooke's lumped masses as its (diagonal) mass matrix, gravity as the external
//   force M g, ImplicitBackwardEulerSparse with one Newton iteration per step (its default real-time setting), the
//   linear system by its Jacobi-preconditioned CG to 1e-6 (how a build without PARDISO/SPOOLES solves it); the
//   clamped and the probe's nodes are its constrained DOFs. Vega's constrained DOFs stay at zero displacement, so
//   the probe's moving displacement d(t) enters through ProbedForceModel: the forces and stiffness at u + d(t).
// - hooke: the quasi-newton integrator (the real-time default) on the same StVK FEM model and on the any-nu-tet
//   spring model at the same nu, and implicit-euler (Newton, Cholesky, its default tolerance) on the StVK model;
//   steps timed in turn with Vega's in one loop.
// Every error is the benchmark's (experiments::relative_error): the largest node distance after the run to
// hooke's implicit Euler with Newton converged to 1e-12 on the same model, relative to its largest displacement.
// On the 1 089-node cylinder Vega is also iterated to convergence and compared with that reference: both codes
// then solve the same discrete problem, so the distance is the cross-check that the physics agree.
// Run: build/release/bench/hooke_bench --benchmark_filter=PeerVega
#include <StVKElementABCDLoader.h>
#include <StVKForceModel.h>
#include <StVKInternalForces.h>
#include <StVKStiffnessMatrix.h>
#include <benchmark/benchmark.h>
#include <forceModel.h>
#include <implicitBackwardEulerSparse.h>
#include <sparseMatrix.h>
#include <tetMesh.h>

#include <algorithm>
#include <chrono>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/core/quantile.hpp>
#include <hooke/experiments/dynamics_benchmark.hpp>
#include <hooke/model/load_case.hpp>
#include <memory>
#include <vector>

namespace {

using namespace hooke;
using hooke::quantile;

constexpr double kYoung = 14630.0, kPoisson = 0.45, kDensity = 1000.0, kDt = 1e-3;
constexpr int kSteps = 300;

// One hooke model of the benchmark cylinder: its problem (bottom clamped) and dynamics (lumped masses, gravity).
struct HookeCylinder {
  calibrate::CalibratedModel cm;
  model::Problem problem;
  solve::Dynamics dynamics;
  experiments::BenchmarkDrag probe;  // `hooke bench`'s: 2 mm along x over half the run's simulated time
  HookeCylinder(int size, const std::string& method) {
    material::Material m;
    m.law = material::Law::kStVK;
    m.youngs_modulus = kYoung;
    m.poisson_ratio = kPoisson;
    calibrate::ModelOptions o;
    o.method = method;
    o.density = kDensity;
    cm = calibrate::calibrate_model(experiments::benchmark_cylinder(size), m, o);
    problem = model::make_problem(calibrate::build_model(cm).model);
    model::fix_nodes(problem, model::make_load_case(cm.mesh, model::LoadKind::kStretch, 0.0).fixed_nodes);
    dynamics = {cm.masses, Vec3(0.0, 0.0, -9.81), 0.0, 0.0};
    probe = {experiments::benchmark_probe_nodes(cm.mesh),
             2e-3,
             0.5 * (kSteps + 1) * kDt,
             Vec3::UnitX(),
             nullptr,
             nullptr,
             Vec3::Zero()};
  }
  /// hooke's simulator of this model with `integrator`'s default options.
  solve::Simulator simulator(solve::Integrator integrator) const {
    solve::SimulatorOptions o;
    o.integrator = integrator;
    return solve::Simulator(problem, dynamics, o);
  }
  VecX reference() const { return experiments::converged_reference(problem, dynamics, kDt, kSteps, probe); }
  // The probe's position at the end of the next step (set before it, untimed, as `hooke bench` does).
  void drag(solve::Simulator& sim) const { probe.before_step(sim, kDt); }
};

// Vega's force model evaluated at u + d, d the probe's displacement (nonzero at its x DOFs only): with the
// probe's DOFs constrained (Vega keeps them at u = 0) this is implicit Euler with the probe's nodes at d(t).
class ProbedForceModel : public ForceModel {
 public:
  ProbedForceModel(ForceModel* inner, std::vector<int> probe_nodes)
      : m_inner(inner), m_probe(std::move(probe_nodes)), m_u(static_cast<size_t>(inner->Getr()), 0.0) {
    r = inner->Getr();
  }
  void set_offset(double x) { m_offset = x; }
  double offset() const { return m_offset; }
  void GetInternalForce(const double* u, double* internal_forces) override {
    m_inner->GetInternalForce(shifted(u), internal_forces);
  }
  void GetTangentStiffnessMatrixTopology(::SparseMatrix** k) override { m_inner->GetTangentStiffnessMatrixTopology(k); }
  void GetTangentStiffnessMatrix(const double* u, ::SparseMatrix* k) override {
    m_inner->GetTangentStiffnessMatrix(shifted(u), k);
  }
  void GetForceAndMatrix(const double* u, double* internal_forces, ::SparseMatrix* k) override {
    m_inner->GetForceAndMatrix(shifted(u), internal_forces, k);
  }

 private:
  const double* shifted(const double* u) {
    std::copy(u, u + r, m_u.begin());
    for (int node : m_probe) m_u[static_cast<size_t>(3 * node)] += m_offset;
    return m_u.data();
  }
  ForceModel* m_inner;
  std::vector<int> m_probe;
  std::vector<double> m_u;
  double m_offset = 0.0;
};

// Vega's StVK model of the same mesh, masses, clamps and gravity, integrated by ImplicitBackwardEulerSparse.
class VegaCylinder {
 public:
  VegaCylinder(const HookeCylinder& h, int newton_iterations, double newton_epsilon) {
    const mesh::Mesh& mesh = h.cm.mesh;
    std::vector<double> vertices(mesh.nodes.data(), mesh.nodes.data() + mesh.nodes.size());
    std::vector<int> tets(mesh.elements.data(), mesh.elements.data() + mesh.elements.size());
    m_mesh = std::make_unique<TetMesh>(mesh.node_count(), vertices.data(), static_cast<int>(tets.size() / 4),
                                       tets.data(), kYoung, kPoisson, kDensity);
    // StVKElementABCDLoader::load and StVKInternalForces read the mesh; gravity is added as an external force.
    m_abcd.reset(StVKElementABCDLoader::load(m_mesh.get()));
    m_forces = std::make_unique<StVKInternalForces>(m_mesh.get(), m_abcd.get());
    m_stiffness = std::make_unique<StVKStiffnessMatrix>(m_forces.get());
    m_stvk = std::make_unique<StVKForceModel>(m_forces.get(), m_stiffness.get());
    m_model = std::make_unique<ProbedForceModel>(m_stvk.get(), h.probe.nodes);
    const int r = 3 * mesh.node_count();
    SparseMatrixOutline outline(r, h.dynamics.mass.data());
    m_mass = std::make_unique<::SparseMatrix>(&outline);
    std::vector<char> constrained = h.problem.fixed_dofs;
    for (int node : h.probe.nodes)
      for (int a = 0; a < 3; ++a) constrained[static_cast<size_t>(3 * node + a)] = true;
    for (int i = 0; i < r; ++i)
      if (constrained[static_cast<size_t>(i)]) m_constrained.push_back(i);
    m_probe = h.probe;  // the protocol and its nodes
    m_integrator = std::make_unique<ImplicitBackwardEulerSparse>(
        r, kDt, m_mass.get(), m_model.get(), static_cast<int>(m_constrained.size()), m_constrained.data(), 0.0, 0.0,
        newton_iterations, newton_epsilon);
    m_gravity.assign(static_cast<size_t>(r), 0.0);
    for (int i = 0; i < r; ++i)
      if (i % 3 == 2 && !constrained[static_cast<size_t>(i)])
        m_gravity[static_cast<size_t>(i)] = -9.81 * h.dynamics.mass(i);
    m_rest = h.problem.model->rest_positions();
  }
  VegaCylinder(const VegaCylinder&) = delete;
  VegaCylinder& operator=(const VegaCylinder&) = delete;

  void step() {
    m_time += kDt;
    m_model->set_offset(m_probe.offset(m_time));
    m_integrator->SetExternalForces(m_gravity.data());
    m_integrator->DoTimestep();
  }
  VecX positions() const {
    VecX x = m_rest + Eigen::Map<const VecX>(m_integrator->Getq(), m_rest.size());
    for (int node : m_probe.nodes) x(3 * node) += m_model->offset();
    return x;
  }

 private:
  std::unique_ptr<TetMesh> m_mesh;
  std::unique_ptr<StVKElementABCD> m_abcd;
  std::unique_ptr<StVKInternalForces> m_forces;
  std::unique_ptr<StVKStiffnessMatrix> m_stiffness;
  std::unique_ptr<StVKForceModel> m_stvk;
  std::unique_ptr<ProbedForceModel> m_model;
  std::unique_ptr<::SparseMatrix> m_mass;
  std::vector<int> m_constrained;
  std::unique_ptr<ImplicitBackwardEulerSparse> m_integrator;
  std::vector<double> m_gravity;
  experiments::BenchmarkDrag m_probe;
  double m_time = 0.0;
  VecX m_rest;
};

void BM_PeerVega(benchmark::State& state) {
  const int size = static_cast<int>(state.range(0));
  const HookeCylinder fem(size, "fem"), springs(size, "any-nu-tet");
  const VecX fem_reference = fem.reference(), springs_reference = springs.reference();
  std::vector<double> vega_ms, fem_ms, springs_ms, newton_ms;
  VecX vega_x, fem_x, springs_x, newton_x;
  auto ms = [](auto t0, auto t1) { return std::chrono::duration<double, std::milli>(t1 - t0).count(); };
  for (auto _ : state) {
    VegaCylinder vega(fem, 1, 1e-6);
    solve::Simulator fem_qn = fem.simulator(solve::Integrator::kQuasiNewton);
    solve::Simulator springs_qn = springs.simulator(solve::Integrator::kQuasiNewton);
    solve::Simulator fem_newton = fem.simulator(solve::Integrator::kImplicitEuler);
    vega.step();  // untimed first steps, as `hooke bench`
    fem.drag(fem_qn);
    springs.drag(springs_qn);
    fem.drag(fem_newton);
    fem_qn.step(kDt);
    springs_qn.step(kDt);
    fem_newton.step(kDt);
    for (int k = 0; k < kSteps; ++k) {
      fem.drag(fem_qn);
      springs.drag(springs_qn);
      fem.drag(fem_newton);
      const auto t0 = std::chrono::steady_clock::now();
      vega.step();
      const auto t1 = std::chrono::steady_clock::now();
      fem_qn.step(kDt);
      const auto t2 = std::chrono::steady_clock::now();
      springs_qn.step(kDt);
      const auto t3 = std::chrono::steady_clock::now();
      fem_newton.step(kDt);
      const auto t4 = std::chrono::steady_clock::now();
      newton_ms.push_back(ms(t3, t4));
      vega_ms.push_back(ms(t0, t1));
      fem_ms.push_back(ms(t1, t2));
      springs_ms.push_back(ms(t2, t3));
    }
    vega_x = vega.positions();
    fem_x = fem_qn.positions();
    springs_x = springs_qn.positions();
    newton_x = fem_newton.positions();
  }
  const VecX& rest = fem.problem.model->rest_positions();
  if (!vega_x.allFinite()) {
    state.SkipWithError("Vega's run produced non-finite positions");
    return;
  }
  state.counters["nodes"] = fem.cm.mesh.node_count();
  state.counters["vega_ms"] = quantile(vega_ms, 0.5);
  state.counters["vega_p99_ms"] = quantile(vega_ms, 0.99);
  state.counters["vega_error"] = experiments::relative_error(vega_x, fem_reference, rest);
  state.counters["hooke_fem_ms"] = quantile(fem_ms, 0.5);
  state.counters["hooke_fem_p99_ms"] = quantile(fem_ms, 0.99);
  state.counters["hooke_fem_error"] = experiments::relative_error(fem_x, fem_reference, rest);
  state.counters["vega_over_hooke_fem"] = quantile(vega_ms, 0.5) / quantile(fem_ms, 0.5);
  state.counters["hooke_fem_newton_ms"] = quantile(newton_ms, 0.5);
  state.counters["hooke_fem_newton_p99_ms"] = quantile(newton_ms, 0.99);
  state.counters["hooke_fem_newton_error"] = experiments::relative_error(newton_x, fem_reference, rest);
  state.counters["vega_over_hooke_fem_newton"] = quantile(vega_ms, 0.5) / quantile(newton_ms, 0.5);
  state.counters["hooke_springs_ms"] = quantile(springs_ms, 0.5);
  state.counters["hooke_springs_p99_ms"] = quantile(springs_ms, 0.99);
  state.counters["hooke_springs_error"] = experiments::relative_error(springs_x, springs_reference, rest);
  if (size == 0) {  // the cross-check: Vega's converged implicit Euler against hooke's
    VegaCylinder converged(fem, 5, 1e-10);
    for (int k = 0; k <= kSteps; ++k) converged.step();
    state.counters["vega_converged_vs_hooke"] = experiments::relative_error(converged.positions(), fem_reference, rest);
  }
}

}  // namespace

BENCHMARK(BM_PeerVega)->Arg(0)->Arg(1)->Iterations(1)->Unit(benchmark::kSecond);
