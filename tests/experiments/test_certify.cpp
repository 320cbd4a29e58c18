// experiments::certify: the certificate shipped with a model is the comparison with the linear FEM, load case by
// load case, at the certificate's strain.
#include <gtest/gtest.h>

#include <hooke/calibrate/model_factory.hpp>
#include <hooke/core/error.hpp>
#include <hooke/experiments/certify.hpp>
#include <hooke/experiments/compare.hpp>
#include <hooke/mesh/generators.hpp>

namespace hooke::experiments {
namespace {

calibrate::CalibratedModel box_model() {
  calibrate::ModelOptions o;
  o.method = "any-nu-tet";
  return calibrate::calibrate_model(mesh::tet_box(0.01, 0.01, 0.02, 2, 2, 4), {material::Law::kLinear, 14630.0, 0.45},
                                    o);
}

TEST(Certify, EachCaseIsTheComparisonAtItsStrain) {
  const calibrate::CalibratedModel model = box_model();
  const std::vector<model::LoadKind> kinds{model::LoadKind::kShear, model::LoadKind::kStretch};
  const std::vector<calibrate::CertificateCase> cases = certify(model, 0.02, 4, kinds);
  ASSERT_EQ(cases.size(), 2u);
  for (size_t k = 0; k < kinds.size(); ++k) {
    CompareOptions o;
    o.load = kinds[k];
    o.strain = 0.02;
    o.load_steps = 1;
    const Comparison c = compare_calibrated(model, o);
    EXPECT_EQ(cases[k].load, model::load_kind_name(kinds[k]));
    EXPECT_EQ(cases[k].strain, 0.02);
    EXPECT_NEAR(cases[k].relative_l2, c.relative_l2, 1e-8 * c.relative_l2);
    EXPECT_NEAR(cases[k].max_error, c.max_error, 1e-8 * c.max_error);
    EXPECT_NEAR(cases[k].mean_error, c.mean_error, 1e-8 * c.mean_error);
    EXPECT_GT(cases[k].relative_l2, 1e-4);  // springs are not the FEM: a certificate of zero would be a bug
  }
}

TEST(Certify, RefusesNoLoadOrNoStrain) {
  const calibrate::CalibratedModel model = box_model();
  EXPECT_THROW(certify(model, 0.0), InvalidArgument);
  EXPECT_THROW(certify(model, std::nan("")), InvalidArgument);
  EXPECT_THROW(certify(model, 0.01, 4, {}), InvalidArgument);
}

}  // namespace
}  // namespace hooke::experiments
