// Simulator::step allocates nothing after the first step (issue: real-time API). A separate executable: it
// replaces the C allocator (malloc and friends, which operator new, CHOLMOD, OpenBLAS and libgomp all call)
// with a counting one, on every thread. Not built with AddressSanitizer, which owns the allocator there.
#include <gtest/gtest.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <hooke/calibrate/method.hpp>
#include <hooke/calibrate/surface_model.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/model/load_case.hpp>
#include <hooke/model/mass.hpp>
#include <hooke/solve/simulator.hpp>
#include <string>

namespace {

std::atomic<long> g_allocations{0};
std::atomic<bool> g_counting{false};

void count() {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace

extern "C" {
void* __libc_malloc(size_t size);
void* __libc_calloc(size_t count, size_t size);
void* __libc_realloc(void* pointer, size_t size);
void* __libc_memalign(size_t alignment, size_t size);

void* malloc(size_t size) {
  count();
  return __libc_malloc(size);
}
void* calloc(size_t n, size_t size) {
  count();
  return __libc_calloc(n, size);
}
void* realloc(void* pointer, size_t size) {
  count();
  return __libc_realloc(pointer, size);
}
void* memalign(size_t alignment, size_t size) {
  count();
  return __libc_memalign(alignment, size);
}
void* aligned_alloc(size_t alignment, size_t size) {
  count();
  return __libc_memalign(alignment, size);
}
int posix_memalign(void** pointer, size_t alignment, size_t size) {
  count();
  *pointer = __libc_memalign(alignment, size);
  return *pointer ? 0 : ENOMEM;
}
}

namespace hooke::solve {
namespace {

struct Case {
  Integrator integrator;
  NewtonLinearSolver linear_solver;
  bool fem;                // StVK FEM model instead of lloyd-tet springs
  bool chebyshev = false;  // local-global with the Chebyshev-Jacobi global step
};

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  std::string name(integrator_name(info.param.integrator));
  if (info.param.linear_solver == NewtonLinearSolver::kConjugateGradient) name += "_cg";
  if (info.param.fem) name += "_fem";
  if (info.param.chebyshev) name += "_chebyshev";
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
}

class StepAllocation : public ::testing::TestWithParam<Case> {};

// A 1 089-node tet cylinder (4 000+ tets: the element loops run on two threads) clamped at the bottom, under
// gravity, with Rayleigh damping and a probe dragging a top node, stepped at 1 ms.
TEST_P(StepAllocation, NoHeapAllocationAfterTheFirstStep) {
  const Case c = GetParam();
  const mesh::Mesh mesh = mesh::tet_cylinder(0.01, 0.02, 10, 8);
  std::shared_ptr<model::Model> model;
  if (c.fem) {
    model = std::make_shared<model::Model>(3, Eigen::Map<const VecX>(mesh.nodes.data(), mesh.nodes.size()));
    model->add(fem::make_elastic_block(mesh, {material::Law::kStVK, 14630.0, 0.25}));
  } else {
    model = calibrate::make_model(
        mesh, calibrate::calibrate(mesh, {{material::Law::kLinear, 14630.0, 0.25}}, calibrate::Method::kLloydTet));
  }
  model::Problem problem = model::make_problem(model);
  model::fix_nodes(problem, model::make_load_case(mesh, model::LoadKind::kStretch, 0.0).fixed_nodes);
  VecX gravity = VecX::Zero(3);
  gravity(2) = -9.81;
  const bool explicit_step =
      c.integrator == Integrator::kSymplecticEuler || c.integrator == Integrator::kVelocityVerlet;
  SimulatorOptions options;
  options.integrator = c.integrator;
  options.newton.linear_solver = c.linear_solver;
  if (c.chebyshev) options.global_solve = GlobalSolve::kChebyshev;
  // Local/global's Kronecker form needs no stiffness damping; the others get both Rayleigh terms.
  Simulator sim(
      problem,
      {model::lumped_masses(mesh, 1000.0), gravity, 2.0, c.integrator == Integrator::kLocalGlobal ? 0.0 : 1e-4},
      options);
  int top = 0;
  for (int i = 0; i < mesh.node_count(); ++i)
    if (mesh.nodes(i, 2) > mesh.nodes(top, 2)) top = i;
  Probe probe{{top}, true, Vec3(0.0, 0.0, 0.0), VecX()};
  sim.set_probe(probe);
  const double dt = explicit_step ? 0.5 * sim.stable_time_step() : 1e-3;
  sim.step(dt);
  sim.step(dt);
  g_allocations = 0;
  g_counting = true;
  int iterations = 0;
  for (int s = 0; s < 20; ++s) {
    probe.offset(0) = 1e-5 * s;  // a haptic device moving: same nodes, new target
    sim.set_probe(probe);
    iterations += sim.step(dt).iterations;
  }
  g_counting = false;
  EXPECT_EQ(g_allocations.load(), 0) << "heap allocations in 20 steps of " << integrator_name(c.integrator);
  EXPECT_TRUE(sim.positions().allFinite());
  if (!explicit_step) {
    EXPECT_GT(iterations, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Integrators, StepAllocation,
    ::testing::Values(Case{Integrator::kSymplecticEuler, NewtonLinearSolver::kCholesky, false},
                      Case{Integrator::kVelocityVerlet, NewtonLinearSolver::kCholesky, false},
                      Case{Integrator::kLocalGlobal, NewtonLinearSolver::kCholesky, false},
                      Case{Integrator::kLocalGlobal, NewtonLinearSolver::kCholesky, false, true},
                      Case{Integrator::kImplicitEuler, NewtonLinearSolver::kConjugateGradient, false},
                      Case{Integrator::kQuasiStatic, NewtonLinearSolver::kConjugateGradient, false},
                      Case{Integrator::kImplicitEulerLinearised, NewtonLinearSolver::kConjugateGradient, false},
                      Case{Integrator::kImplicitEuler, NewtonLinearSolver::kConjugateGradient, true},
                      Case{Integrator::kVelocityVerlet, NewtonLinearSolver::kCholesky, true},
                      Case{Integrator::kQuasiNewton, NewtonLinearSolver::kCholesky, false},
                      Case{Integrator::kQuasiNewton, NewtonLinearSolver::kCholesky, true}),
    case_name);

// The surface model (scheme D: blended anchors, the volume penalty with the interaction weights following the
// probe) steps without heap allocation too, explicitly and with implicit Euler (residual line search).
TEST(SurfaceStepAllocation, NoHeapAllocationAfterTheFirstStep) {
  for (const Integrator integrator : {Integrator::kSymplecticEuler, Integrator::kImplicitEuler}) {
    const calibrate::SurfaceModel s =
        calibrate::make_surface_model(mesh::uv_sphere_surface(12, 20, 0.05), {material::Law::kLinear, 1000.0, 0.3});
    model::Problem problem = model::make_problem(s.model);
    problem.interaction = model::Interaction{s.mesh.nodes.row(0).transpose(), Vec3(0, 0, -1), 0.1};
    VecX gravity = VecX::Zero(3);
    gravity(2) = -9.81;
    SimulatorOptions options;
    options.integrator = integrator;
    options.newton.linear_solver = NewtonLinearSolver::kConjugateGradient;
    Simulator sim(problem, {s.masses, gravity, 2.0, 0.0}, options);
    Probe probe{{0}, false, VecX(), Vec3(0.0, 0.0, 0.0)};
    const double dt = integrator == Integrator::kSymplecticEuler ? 0.5 * sim.stable_time_step() : 1e-3;
    sim.set_probe(probe);
    sim.step(dt);
    sim.step(dt);
    g_allocations = 0;
    g_counting = true;
    for (int k = 0; k < 20; ++k) {
      probe.force(2) = -1e-4 * k;
      sim.set_probe(probe);
      sim.step(dt);
    }
    g_counting = false;
    EXPECT_EQ(g_allocations.load(), 0) << integrator_name(integrator);
    EXPECT_TRUE(sim.positions().allFinite());
  }
}

}  // namespace
}  // namespace hooke::solve
