// Spring models at large strain (docs/methods/large_strain.md): displacement-controlled comparisons against the
// Neo-Hookean FEM, the term law fitted by measurement, the certificate over a strain range, and the model holding
// where the Hookean one collapses.
#include <gtest/gtest.h>

#include <hooke/calibrate/model_factory.hpp>
#include <hooke/calibrate/model_file.hpp>
#include <hooke/core/error.hpp>
#include <hooke/experiments/certify.hpp>
#include <hooke/experiments/compare.hpp>
#include <hooke/experiments/term_law_fit.hpp>
#include <hooke/io/mesh_io.hpp>

namespace hooke::experiments {
namespace {

using material::Law;

calibrate::CalibratedModel cylinder_model(double nu, double m = 1.0, double q = 1.0,
                                          const char* mesh = "/cylinder.msh") {
  calibrate::ModelOptions o;
  o.method = "stiffness-fit-volume";
  o.spring_exponent = m;
  o.volume_exponent = q;
  return calibrate::calibrate_model(io::read_mesh(std::string(HOOKE_MESH_DATA) + mesh), {Law::kLinear, 14630.0, nu}, o);
}

CompareOptions pressed(model::LoadKind kind, double strain) {
  CompareOptions o;
  o.load = kind;
  o.strain = strain;
  o.reference = Law::kNeoHookean;
  o.control = model::LoadControl::kDisplacement;
  return o;
}

// At small strain every law is the calibrated linear model: the force on the top agrees with the linear FEM's as
// the displacements do, for the Hookean and the large-strain law alike.
TEST(LargeStrain, AtSmallStrainEveryLawIsTheLinearModel) {
  for (auto [m, q] : {std::pair{1.0, 1.0}, std::pair{0.0, -1.0}}) {
    const calibrate::CalibratedModel model = cylinder_model(0.45, m, q);
    CompareOptions o = pressed(model::LoadKind::kStretch, 1e-4);
    o.reference = Law::kLinear;
    const Comparison c = compare_calibrated(model, o);
    ASSERT_EQ(c.spring_report.status, solve::SolveStatus::kConverged);
    EXPECT_LT(c.relative_l2, 0.15);
    EXPECT_LT(c.reaction_error, 0.15);
    EXPECT_EQ(c.load.control, model::LoadControl::kDisplacement);
  }
  // The two laws' responses at 0.01 % strain are the same to the first order.
  const CompareOptions o = pressed(model::LoadKind::kCompress, 1e-4);
  const Comparison a = compare_calibrated(cylinder_model(0.45), o);
  const Comparison b = compare_calibrated(cylinder_model(0.45, 0.0, -1.0), o);
  const VecX rest = Eigen::Map<const VecX>(a.fem_mesh.nodes.data(), a.fem_mesh.nodes.size());
  EXPECT_LT((a.spring_positions - b.spring_positions).norm(), 1e-3 * (a.spring_positions - rest).norm());
  EXPECT_LT((a.spring_reaction - b.spring_reaction).norm(), 1e-3 * a.spring_reaction.norm());
}

// The fitted law is measured better than the Hookean one at 20 % under displacement control, never worse, and the
// model written with it reads back with the same law.
TEST(LargeStrain, TheFittedLawBeatsHookeanSpringsAt20PercentAndRoundTrips) {
  calibrate::CalibratedModel model = cylinder_model(0.45);
  TermLawFitOptions fo;
  fo.law = Law::kNeoHookean;
  fo.strain_range = 0.2;
  const TermLawFit fit = fit_term_law(model, fo);
  // On this 87-node cylinder the calibrated model's force is 13 % off already at 1 % strain (the small-strain fit's
  // own error, which the law cannot change): the law removes what large strain adds to it.
  EXPECT_LE(fit.worst_error, fit.hookean_error);
  EXPECT_LT(fit.worst_error, 0.15) << fit.summary;
  EXPECT_LT(fit.worst_error, 0.5 * fit.hookean_error) << fit.summary;
  EXPECT_GT(fit.hookean_error, 0.3) << fit.summary;  // Hookean springs: the force 42 % off in 20 % stretch
  EXPECT_GE(fit.evaluations, 12);
  model.springs.spring_exponent = fit.spring_exponent;
  model.springs.volume_exponent = fit.volume_exponent;
  EXPECT_NEAR(term_law_error(model, fo), fit.worst_error, 1e-9);
  model.certificate = certify_range(model, Law::kNeoHookean, 0.2);
  ASSERT_EQ(model.certificate.size(), 6u);
  for (const calibrate::CertificateCase& c : model.certificate) {
    EXPECT_EQ(c.control, "displacement");
    EXPECT_EQ(c.reference, "neohookean");
    EXPECT_LT(c.relative_l2, 0.15) << c.load << " " << c.strain;
    EXPECT_LT(c.force_error, 0.15) << c.load << " " << c.strain;
  }
  const calibrate::CalibratedModel back = calibrate::parse_model(calibrate::model_json(model), "m.json");
  EXPECT_EQ(back.springs.spring_exponent, fit.spring_exponent);
  EXPECT_EQ(back.springs.volume_exponent, fit.volume_exponent);
  EXPECT_EQ(back.certificate.size(), 6u);
  EXPECT_EQ(back.certificate[4].control, "displacement");
  EXPECT_EQ(back.certificate[4].force_error, model.certificate[4].force_error);
  // A Hookean model's file has no term law (files of earlier models stay byte for byte).
  EXPECT_EQ(calibrate::model_json(cylinder_model(0.45)).find("term_law"), std::string::npos);
  std::string bad = calibrate::model_json(model);
  bad.replace(bad.find("\"spring_exponent\": ") + 19, 1, "9");
  EXPECT_THROW(calibrate::parse_model(bad, "bad.json"), ParseError);
}

// A 40 % press: the barrier volume terms keep every tet upright and the equilibrium is stable.
TEST(LargeStrain, A40PercentPressConverges) {
  const Comparison c = compare_calibrated(cylinder_model(0.45, 0.0, -1.0), pressed(model::LoadKind::kCompress, 0.4));
  ASSERT_EQ(c.fem_report.status, solve::SolveStatus::kConverged) << c.fem_report.message;
  ASSERT_EQ(c.spring_report.status, solve::SolveStatus::kConverged) << c.spring_report.message;
  EXPECT_LT(c.relative_l2, 0.15);
  EXPECT_GT(c.spring_reaction.dot(c.load.direction), 0.0);
}

// The traction-controlled 12 % compression at nu = 0.3 on the cylinder with a hole: the Neo-Hookean FEM holds, the
// Hookean springs reach a limit point short of the load (at 98 %, measured by `hooke compare`; finding it takes a
// minute of halved load steps, too long for this suite), the large-strain law (log springs, barrier volume terms)
// holds, stable, near the FEM.
TEST(LargeStrain, TwelvePercentCompressionAtNuThreeTenthsHoldsWithTheLargeStrainLaw) {
  CompareOptions o;
  o.load = model::LoadKind::kCompress;
  o.strain = 0.12;
  o.reference = Law::kNeoHookean;
  const Comparison held = compare_calibrated(cylinder_model(0.3, 0.0, -2.0, "/cylinder_hole.msh"), o);
  ASSERT_EQ(held.fem_report.status, solve::SolveStatus::kConverged);
  ASSERT_EQ(held.spring_report.status, solve::SolveStatus::kConverged) << held.spring_report.message;
  EXPECT_LT(held.relative_l2, 0.15);
}

// auto over a strain range fits the any-nu models beside the small-strain pick and keeps the least worst error.
TEST(LargeStrain, AutoOverARangeKeepsTheBestFittedModel) {
  calibrate::ModelOptions o;
  const calibrate::CalibratedModel picked =
      calibrate::calibrate_model(io::read_mesh(HOOKE_MESH_DATA "/cylinder.msh"), {Law::kLinear, 14630.0, 0.45}, o);
  TermLawFitOptions fo;
  fo.strain_range = 0.2;
  const calibrate::CalibratedModel chosen = choose_for_range(picked, fo);
  EXPECT_NE(chosen.choice.find("stiffness-fit-volume"), std::string::npos) << chosen.choice;
  EXPECT_NE(chosen.choice.find("any-nu-tet"), std::string::npos) << chosen.choice;
  const double chosen_error = term_law_error(chosen, fo);
  for (const char* method : {"stiffness-fit-volume", "any-nu-tet"}) {
    o.method = method;
    const calibrate::CalibratedModel other =
        with_fitted_law(calibrate::calibrate_model(picked.mesh, picked.material, o), fo);
    EXPECT_LE(chosen_error, term_law_error(other, fo) + 1e-9) << method;
  }
}

// St. Venant-Kirchhoff stiffens in stretch and softens in compression: its fitted springs are on the Green-strain side
// (m > 1), the reverse of a Neo-Hookean fit, and better than Hookean ones.
TEST(LargeStrain, AStVKFitChoosesSpringsThatStiffenInStretch) {
  TermLawFitOptions fo;
  fo.law = Law::kStVK;
  fo.strain_range = 0.12;
  const TermLawFit fit = fit_term_law(cylinder_model(0.3), fo);
  EXPECT_GT(fit.spring_exponent, 1.0) << fit.summary;
  EXPECT_LT(fit.worst_error, fit.hookean_error) << fit.summary;
}

TEST(LargeStrain, TheFitRefusesWhatItCannotFit) {
  TermLawFitOptions fo;
  fo.strain_range = 0.7;
  EXPECT_THROW(fit_term_law(cylinder_model(0.45), fo), InvalidArgument);
  calibrate::ModelOptions fem;
  fem.method = "fem";
  fo.strain_range = 0.2;
  EXPECT_THROW(fit_term_law(calibrate::calibrate_model(io::read_mesh(HOOKE_MESH_DATA "/cylinder.msh"),
                                                       {Law::kNeoHookean, 14630.0, 0.45}, fem),
                            fo),
               InvalidArgument);
}

}  // namespace
}  // namespace hooke::experiments
