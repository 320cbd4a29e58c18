// Every enum a user names (on the command line, in scripts, model files and Python): each value's name reads back
// as that value, the names differ, and an unknown name is refused with the names to use.
#include <gtest/gtest.h>

#include <hooke/calibrate/calibrated_model.hpp>
#include <hooke/calibrate/method.hpp>
#include <hooke/calibrate/surface_model.hpp>
#include <hooke/core/error.hpp>
#include <hooke/interactive/haptic_model.hpp>
#include <hooke/material/material.hpp>
#include <hooke/mesh/tetrahedralize.hpp>
#include <hooke/model/load_case.hpp>
#include <hooke/solve/integrator.hpp>
#include <hooke/solve/newton.hpp>
#include <set>
#include <string>
#include <vector>

namespace hooke {
namespace {

template <typename Enum, typename Name, typename FromName>
void expect_round_trip(const std::vector<Enum>& values, Name name, FromName from_name) {
  std::set<std::string> seen;
  for (const Enum v : values) {
    const std::string n(name(v));
    EXPECT_NE(n, "unknown");
    EXPECT_TRUE(seen.insert(n).second) << "two values named " << n;
    EXPECT_EQ(from_name(n), v) << n;
  }
  try {
    from_name("no-such-name");
    ADD_FAILURE() << "'no-such-name' was accepted";
  } catch (const InvalidArgument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("unknown "), std::string::npos) << what;
    EXPECT_NE(what.find(*seen.begin()), std::string::npos) << "the names to use are not listed: " << what;
  }
}

TEST(EnumNames, EveryNamedEnumReadsBack) {
  using namespace calibrate;
  expect_round_trip<Method>({Method::kVanGelder, Method::kLloydEquilateral, Method::kLloydTriangle,
                             Method::kLloydSquare, Method::kLloydTet, Method::kLloydTetVolume, Method::kStiffnessFit,
                             Method::kStiffnessFitVolume, Method::kAnyNuTet, Method::kAnyNuTriangle},
                            method_name, method_from_name);
  expect_round_trip<SurfaceScheme>({SurfaceScheme::kA, SurfaceScheme::kB, SurfaceScheme::kC, SurfaceScheme::kD},
                                   surface_scheme_name, surface_scheme_from_name);
  EXPECT_EQ(surface_scheme_from_name("d"), SurfaceScheme::kD);  // also in lower case
  expect_round_trip<mesh::SurfaceMeshing>({mesh::SurfaceMeshing::kRemesh, mesh::SurfaceMeshing::kKeep},
                                          mesh::surface_meshing_name, mesh::surface_meshing_from_name);
  using material::Law;
  using material::Plane;
  expect_round_trip<Law>({Law::kLinear, Law::kStVK, Law::kNeoHookean}, material::law_name, material::law_from_name);
  expect_round_trip<Plane>({Plane::kStress, Plane::kStrain}, material::plane_name, material::plane_from_name);
  using model::LoadKind;
  expect_round_trip<model::LoadKind>({model::LoadKind::kStretch, model::LoadKind::kCompress, model::LoadKind::kShear},
                                     model::load_kind_name, model::load_kind_from_name);
  using solve::Integrator;
  expect_round_trip<Integrator>({Integrator::kSymplecticEuler, Integrator::kVelocityVerlet, Integrator::kImplicitEuler,
                                 Integrator::kImplicitEulerLinearised, Integrator::kLocalGlobal,
                                 Integrator::kQuasiNewton, Integrator::kQuasiStatic},
                                solve::integrator_name, solve::integrator_from_name);
  expect_round_trip<solve::GlobalSolve>({solve::GlobalSolve::kDirect, solve::GlobalSolve::kChebyshev},
                                        solve::global_solve_name, solve::global_solve_from_name);
  using solve::QuasiNewtonHessian;
  expect_round_trip<QuasiNewtonHessian>(
      {QuasiNewtonHessian::kAuto, QuasiNewtonHessian::kRest, QuasiNewtonHessian::kIsotropic},
      solve::quasi_newton_hessian_name, solve::quasi_newton_hessian_from_name);
  using solve::NewtonLinearSolver;
  expect_round_trip<NewtonLinearSolver>({NewtonLinearSolver::kCholesky, NewtonLinearSolver::kConjugateGradient},
                                        solve::newton_linear_solver_name, solve::newton_linear_solver_from_name);
  using interactive::HapticStiffness;
  expect_round_trip<HapticStiffness>({HapticStiffness::kNone, HapticStiffness::kCondensed, HapticStiffness::kSecant},
                                     interactive::haptic_stiffness_name, interactive::haptic_stiffness_from_name);
  expect_round_trip<ModelKind>({ModelKind::kSurface, ModelKind::kFem, ModelKind::kFile}, model_kind_name,
                               model_kind_of_method);
}

}  // namespace
}  // namespace hooke
