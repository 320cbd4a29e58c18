// The assembled surface model of Arnab & Raja: schemes A-D, rigid motions, the volume penalty's effect, the
// re-extracted Young's modulus, and the conservative variant's derivatives.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <hooke/calibrate/surface_model.hpp>
#include <hooke/core/error.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/model/problem.hpp>
#include <hooke/solve/simulator.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <iostream>
#include <support/block_checks.hpp>

namespace hooke::calibrate {
namespace {

const material::Material kMaterial{material::Law::kLinear, 100.0, 0.3};

SurfaceModel build(SurfaceScheme scheme, SurfaceOptions o = {}, const material::Material& mat = kMaterial) {
  o.scheme = scheme;
  return make_surface_model(mesh::uv_sphere_surface(8, 12, 0.05), mat, o);
}

TEST(SurfaceModel, SchemesDistributeMassAndStiffnessAsThePaperLists) {
  const SurfaceModel a = build(SurfaceScheme::kA), b = build(SurfaceScheme::kB), c = build(SurfaceScheme::kC),
                     d = build(SurfaceScheme::kD);
  const double mass = 1000.0 * a.discretisation.volume;
  for (const SurfaceModel* s : {&a, &b, &c, &d}) EXPECT_NEAR(s->masses.sum(), 3.0 * mass, 1e-12 * mass);
  EXPECT_LT(a.masses.maxCoeff() - a.masses.minCoeff(), 1e-15);                      // A: uniform mass
  EXPECT_GT(b.masses.maxCoeff() - b.masses.minCoeff(), 0.1 * b.masses.maxCoeff());  // B-D: irregular
  EXPECT_EQ(a.k_normal.maxCoeff(), a.k_normal.minCoeff());                          // A, B: uniform inner stiffness
  EXPECT_EQ(b.k_normal.maxCoeff(), b.k_normal.minCoeff());
  EXPECT_GT(c.k_normal.maxCoeff(), 1.1 * c.k_normal.minCoeff());  // C, D: irregular
  EXPECT_NEAR(b.k_normal(0), c.k_normal.mean(), 1e-12 * c.k_normal.mean());
  EXPECT_EQ(c.anchors->law(), surface::AnchorLaw::kSingle);
  EXPECT_EQ(d.anchors->law(), surface::AnchorLaw::kBlend);
  EXPECT_EQ(c.volume, nullptr);
  ASSERT_NE(d.volume, nullptr);
  // K_G / K_E: the shear modulus reading 1/(2(1+nu)), or the printed 1/(2(1-nu)).
  EXPECT_NEAR(d.k_shear(3) / d.k_normal(3), 1.0 / 2.6, 1e-14);
  SurfaceOptions printed;
  printed.shear_factor = ShearFactor::kPrinted;
  EXPECT_NEAR(build(SurfaceScheme::kD, printed).k_shear(3) / d.k_normal(3), 1.0 / 1.4, 1e-14);
  EXPECT_NEAR(d.k_bulk(3) / d.k_normal(3), 1.0 / (3.0 * 0.4), 1e-14);
}

// A rigid motion of the undeformed object stretches no membrane spring and keeps the volume; only the anchors
// (fixed in the world, not to the body) pull back.
TEST(SurfaceModel, RigidMotionLoadsOnlyTheAnchors) {
  for (surface::VolumeForce f : {surface::VolumeForce::kNodal, surface::VolumeForce::kEnergy}) {
    SurfaceOptions o;
    o.volume_force = f;
    const SurfaceModel s = build(SurfaceScheme::kD, o);
    const Eigen::Matrix3d r = Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    VecX x = s.model->rest_positions();
    for (Eigen::Index i = 0; i < x.size() / 3; ++i) x.segment<3>(3 * i) = r * x.segment<3>(3 * i) + Vec3(0.01, 0, 0);
    double anchors = 0.0;
    for (const auto& block : s.model->blocks()) {
      const double g = test::block_gradient(*block, x).norm();
      if (block->name() == "anchors")
        anchors = g;
      else
        EXPECT_LT(g, 1e-12) << block->name() << " " << surface::volume_force_name(f);
    }
    EXPECT_GT(anchors, 1e-3);
  }
}

// The conservative variant (tensor anchors, bulk energy) is a potential model: forces = -dE/dx.
TEST(SurfaceModel, ConservativeVariantForcesAreEnergyDerivatives) {
  SurfaceOptions o;
  o.anchor_law = surface::AnchorLaw::kTensor;
  o.volume_force = surface::VolumeForce::kEnergy;
  const SurfaceModel s = build(SurfaceScheme::kD, o);
  EXPECT_TRUE(s.model->conservative());
  VecX x = s.model->rest_positions();
  for (Eigen::Index i = 0; i < x.size(); ++i) x(i) += 1e-3 * std::sin(1.0 + 2.0 * static_cast<double>(i));
  const VecX g = s.model->gradient(x);
  const VecX g_fd = test::fd_gradient([&](const VecX& y) { return s.model->energy(y); }, x, 1e-7);
  EXPECT_LT((g - g_fd).norm(), 1e-6 * g.norm());
  EXPECT_FALSE(build(SurfaceScheme::kD).model->conservative());
}

// Pressure on the top face of a cube: with only anchors (no membrane) every top node of scheme C moves by
// sigma L' / E, so the strain u / L' returns E exactly; scheme D's corner and edge nodes blend towards K_G.
TEST(SurfaceModel, TopFacePressureReturnsYoungsModulusForSchemeC) {
  SurfaceOptions o;
  o.membrane_thickness = 0.0;
  o.scheme = SurfaceScheme::kC;
  const double a = 0.1;
  const SurfaceModel s = make_surface_model(mesh::cube_surface(6, a), kMaterial, o);
  model::Problem p = model::make_problem(s.model);
  p.external_force = VecX::Zero(s.model->dof_count());
  for (int t = 0; t < s.mesh.element_count(); ++t) {
    bool top = true;
    for (int k = 0; k < 3; ++k) top = top && s.mesh.nodes(s.mesh.elements(t, k), 2) > a - 1e-12;
    if (top)
      for (int k = 0; k < 3; ++k) p.external_force(3 * s.mesh.elements(t, k) + 2) -= 1.0 * (a * a / 72.0) / 3.0;
  }
  const solve::StaticResult r = solve::static_equilibrium(p);
  solve::require_converged(r.report);
  for (int i = 0; i < s.mesh.node_count(); ++i)
    if (s.mesh.nodes(i, 2) > a - 1e-12 && s.mesh.nodes(i, 0) > 1e-12 && s.mesh.nodes(i, 0) < a - 1e-12 &&
        s.mesh.nodes(i, 1) > 1e-12 && s.mesh.nodes(i, 1) < a - 1e-12) {
      const double u = s.model->rest_positions()(3 * i + 2) - r.positions(3 * i + 2);
      EXPECT_NEAR(1.0 / (u / (a / 2)), 100.0, 1e-9) << "node " << i;  // sigma = 1 Pa
    }
}

// Under the same constant load the volume penalty keeps the volume closer to V0 than the same model without it.
TEST(SurfaceModel, VolumePenaltyReducesTheVolumeDeviation) {
  auto deviation = [](bool penalty) {
    SurfaceOptions o;
    o.volume_penalty = penalty;
    o.anchor_law = surface::AnchorLaw::kSingle;
    const SurfaceModel s = build(SurfaceScheme::kD, o);
    model::Problem p = model::make_problem(s.model);
    p.external_force = VecX::Zero(s.model->dof_count());
    // Squeeze: push every node towards the centre plane z = 0 (a constant load, 1 mN per node).
    for (int i = 0; i < s.mesh.node_count(); ++i)
      p.external_force(3 * i + 2) = s.mesh.nodes(i, 2) > 0 ? -1e-3 : (s.mesh.nodes(i, 2) < 0 ? 1e-3 : 0.0);
    const solve::StaticResult r = solve::static_equilibrium(p);
    solve::require_converged(r.report);
    return std::abs(mesh::enclosed_volume(s.mesh.elements, r.positions) / s.discretisation.volume - 1.0);
  };
  const double with = deviation(true), without = deviation(false);
  std::cout << "[volume] deviation with penalty " << with << ", without " << without << "\n";
  EXPECT_GT(without, 1e-3);
  EXPECT_LT(with, 0.7 * without);
}

// The surface model is a model like any other: under gravity with damping, the conservative variant (implicit
// Euler) and the paper's scheme D (symplectic Euler, implicit Euler, quasi-static) settle to the static solver's
// equilibrium; local/global, which needs springs only, refuses it.
TEST(SurfaceModel, RunsInTheIntegratorsAndSettlesToTheStaticEquilibrium) {
  VecX g = VecX::Zero(3);
  g(2) = -9.81;
  auto settled_error = [&](const SurfaceModel& s, solve::Integrator integrator, double dt, int steps) {
    model::Problem statics = model::make_problem(s.model);
    statics.external_force = VecX::Zero(s.model->dof_count());
    for (Eigen::Index i = 0; i < statics.external_force.size(); ++i) statics.external_force(i) = s.masses(i) * g(i % 3);
    const solve::StaticResult ref = solve::static_equilibrium(statics);
    solve::require_converged(ref.report);
    solve::SimulatorOptions o;
    o.integrator = integrator;
    solve::Simulator sim(model::make_problem(s.model), {s.masses, g, 200.0, 0.0}, o);
    for (int k = 0; k < steps; ++k) sim.step(dt);
    const double sag = (ref.positions - s.model->rest_positions()).cwiseAbs().maxCoeff();
    return (sim.positions() - ref.positions).cwiseAbs().maxCoeff() / sag;
  };
  SurfaceOptions conservative;
  conservative.anchor_law = surface::AnchorLaw::kTensor;
  conservative.volume_force = surface::VolumeForce::kEnergy;
  const material::Material stiff{material::Law::kLinear, 1e5, 0.3};  // sags by about 1 % of its size
  const SurfaceModel c = build(SurfaceScheme::kD, conservative, stiff);
  const double implicit = settled_error(c, solve::Integrator::kImplicitEuler, 1e-3, 300);
  const SurfaceModel d = build(SurfaceScheme::kD, {}, stiff);
  solve::SimulatorOptions o;
  o.integrator = solve::Integrator::kSymplecticEuler;
  const double dt = 0.5 * solve::Simulator(model::make_problem(d.model), {d.masses, g, 0.0, 0.0}, o).stable_time_step();
  const double explicit_error = settled_error(d, solve::Integrator::kSymplecticEuler, dt, static_cast<int>(0.3 / dt));
  std::cout << "[surface dynamics] settled |x - x_static| / sag: implicit Euler (conservative variant) " << implicit
            << ", symplectic Euler (scheme D, dt " << dt << " s) " << explicit_error << "\n";
  EXPECT_LT(implicit, 1e-4);
  EXPECT_LT(explicit_error, 1e-4);
  // Scheme D (no potential) in implicit Euler and quasi-static: Newton backtracks on the residual instead.
  const double implicit_d = settled_error(d, solve::Integrator::kImplicitEuler, 1e-3, 300);
  const double quasi_static_d = settled_error(d, solve::Integrator::kQuasiStatic, 1e-3, 1);
  std::cout << "[surface dynamics] scheme D: implicit Euler " << implicit_d << ", quasi-static " << quasi_static_d
            << "\n";
  EXPECT_LT(implicit_d, 1e-4);
  EXPECT_LT(quasi_static_d, 1e-4);
  o.integrator = solve::Integrator::kLocalGlobal;
  EXPECT_THROW(solve::Simulator(model::make_problem(d.model), {d.masses, g, 0.0, 0.0}, o), InvalidArgument);
}

}  // namespace
}  // namespace hooke::calibrate
