// A real scanned surface no one on the project made (CGAL's femur, Debian libcgal-demo) to a simulated model:
// tetrahedralized by the model factory, calibrated with a volume-term method at nu = 0.45, certified against the
// linear FEM of the same tets, and 300 steps of gravity with no inverted element (the integrators' guard throws).
#include <gtest/gtest.h>

#include <filesystem>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/calibrate/surface_model.hpp>
#include <hooke/core/error.hpp>
#include <hooke/experiments/certify.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/solve/simulation.hpp>

namespace hooke::experiments {
namespace {

TEST(ScanToModel, FemurIsTetrahedralizedCalibratedCertifiedAndSimulated) {
  const std::filesystem::path path = std::filesystem::path(HOOKE_SCAN_DATA) / "femur.off";
  ASSERT_TRUE(std::filesystem::exists(path)) << path << " is missing: scripts/setup.sh installs libcgal-demo";
  io::ReadOptions ro;
  ro.metres_per_unit = 0.45;  // CGAL's surfaces are scaled to a unit box: a 45 cm femur
  const mesh::Mesh surface = io::read_mesh(path, ro);
  // A stiff rubber: self-weight strain rho g L / E about 4e-3, small enough for the linear certificate.
  const material::Material rubber{material::Law::kLinear, 1e6, 0.45};
  calibrate::ModelOptions mo;
  mo.method = "stiffness-fit-volume";
  const calibrate::CalibratedModel model = calibrate::calibrate_model(surface, rubber, mo);
  EXPECT_EQ(model.mesh.kind, mesh::ElementKind::kTet);
  EXPECT_NE(model.meshing.find("surface nodes preserved"), std::string::npos) << model.meshing;
  EXPECT_GT(model.springs.volume_tets.rows(), 0);
  // Below the slender bone's buckling strain (docs/meshing.md): the linear reference stands for it.
  for (const calibrate::CertificateCase& c : certify(model, 1e-3, 4))
    EXPECT_LE(c.relative_l2, 0.15) << c.load << ": " << c.relative_l2;
  solve::SimulationOptions so;
  so.steps = 300;
  so.dynamics.gravity = true;
  so.dynamics.damping_mass = 10.0;
  const solve::SimulationSummary s = solve::simulate(model, so, [](int, double, const VecX&, const VecX&) {});
  EXPECT_EQ(s.step_ms.size(), 300u);
  EXPECT_EQ(s.not_converged, 0);
}

TEST(ScanToModel, SurfaceModelOfAFemurThatIsNotStarShaped) {
  const std::filesystem::path path = std::filesystem::path(HOOKE_SCAN_DATA) / "femur.off";
  ASSERT_TRUE(std::filesystem::exists(path)) << path << " is missing: scripts/setup.sh installs libcgal-demo";
  io::ReadOptions ro;
  ro.metres_per_unit = 0.45;
  const mesh::Mesh surface = io::read_mesh(path, ro);
  const material::Material tissue{material::Law::kLinear, 3000.0, 0.45};
  // The radial construction refuses the femur from its centroid; the depth reading takes it.
  const calibrate::SurfaceModel s = calibrate::make_surface_model(surface, tissue);
  EXPECT_FALSE(s.radial);
  EXPECT_GT(s.discretisation.normal_length.minCoeff(), 0.0);
  EXPECT_GT(s.k_normal.minCoeff(), 0.0);
  calibrate::ModelOptions mo;
  mo.method = "surface";
  const calibrate::CalibratedModel model = calibrate::calibrate_model(surface, tissue, mo);
  ASSERT_TRUE(model.surface.has_value());
  EXPECT_EQ(model.mesh.kind, mesh::ElementKind::kSurfaceTriangle);  // not tetrahedralized
  EXPECT_NEAR(model.masses.sum() / 3.0, 1000.0 * s.discretisation.volume, 1e-9 * model.masses.sum());
  // 300 steps of gravity with the default integrator (quasi-newton, whose initial Hessian is the isotropic one for the
  // surface model's approximate Hessian: the rest one stalled at step 5), in a stiff rubber whose self-weight strain
  // is about 4e-3; every step converged, nothing inverted, the body hangs on its anchors at rest.
  const calibrate::CalibratedModel rubber =
      calibrate::calibrate_model(surface, {material::Law::kLinear, 1e6, 0.45}, mo);
  solve::SimulationOptions so;
  so.steps = 300;
  so.dynamics.gravity = true;
  so.dynamics.damping_mass = 10.0;
  VecX last;
  const solve::SimulationSummary run =
      solve::simulate(rubber, so, [&](int, double, const VecX& u, const VecX&) { last = u; });
  EXPECT_EQ(run.step_ms.size(), 300u);
  EXPECT_EQ(run.not_converged, 0);
  EXPECT_LT(run.iterations, 8 * 300);
  const double sag = last.cwiseAbs().maxCoeff();
  EXPECT_GT(sag, 0.0);
  EXPECT_LT(sag, 0.01 * 0.45);  // a small fraction of the bone's length
}

}  // namespace
}  // namespace hooke::experiments
