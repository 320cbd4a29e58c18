// Anchors (Arnab & Raja Eq. 2 and the K_E / K_G blend): the stiffness is K_E along the normal and K_G across
// it; forces are derivatives of the energy where one exists; the blend's Hessian is the symmetric part of its
// force Jacobian.
#include <gtest/gtest.h>

#include <hooke/surface/anchor_block.hpp>
#include <support/block_checks.hpp>

namespace hooke::surface {
namespace {

struct TwoAnchors {
  VecX rest = (VecX(6) << 0.0, 0.0, 0.0, 1.0, 0.5, -0.2).finished();
  RowMatX normals = (RowMatX(2, 3) << 0.0, 0.0, 1.0, 0.6, 0.0, 0.8).finished();
  VecX k_e = (VecX(2) << 300.0, 200.0).finished();
  VecX k_g = (VecX(2) << 100.0, 50.0).finished();
  AnchorBlock make(AnchorLaw law) const { return AnchorBlock(rest, normals, k_e, k_g, law); }
};

TEST(AnchorBlock, StiffnessIsKEAlongTheNormalAndKGAcrossIt) {
  const TwoAnchors a;
  for (AnchorLaw law : {AnchorLaw::kBlend, AnchorLaw::kTensor}) {
    const AnchorBlock b = a.make(law);
    for (double s : {1e-3, -2e-3}) {
      VecX x = a.rest;
      x.segment<3>(3) += s * a.normals.row(1).transpose();  // a normal force (push or pull)
      VecX g = test::block_gradient(b, x);
      EXPECT_LT((g.segment<3>(3) - 200.0 * s * a.normals.row(1).transpose()).norm(), 1e-12) << anchor_law_name(law);
      x = a.rest;
      const Vec3 tangent(0.8, 0.0, -0.6);
      x.segment<3>(3) += s * tangent;
      g = test::block_gradient(b, x);
      EXPECT_LT((g.segment<3>(3) - 50.0 * s * tangent).norm(), 1e-12) << anchor_law_name(law);
    }
  }
  // Oblique: the paper's blend weights by |cos|, the tensor by cos^2.
  const Vec3 oblique = (Vec3(0, 0, 1) + Vec3(1, 0, 0)).normalized();
  const double smooth = (std::sqrt(0.5 + 1e-4) - 0.01) / (std::sqrt(1.0 + 1e-4) - 0.01);  // |cos| smoothed at 0
  EXPECT_NEAR(smooth, std::sqrt(0.5), 0.01);
  EXPECT_NEAR(a.make(AnchorLaw::kBlend).stiffness_along(0, oblique), 100.0 + 200.0 * smooth, 1e-12);
  EXPECT_NEAR(a.make(AnchorLaw::kTensor).stiffness_along(0, oblique), 100.0 + 200.0 * 0.5, 1e-12);
  EXPECT_NEAR(a.make(AnchorLaw::kSingle).stiffness_along(0, oblique), 300.0, 1e-12);
}

TEST(AnchorBlock, ConservativeLawsAreDerivativesOfTheirEnergy) {
  const TwoAnchors a;
  VecX x = a.rest;
  x += (VecX(6) << 1e-3, -2e-3, 3e-3, 2e-3, 1e-3, -1e-3).finished();
  for (AnchorLaw law : {AnchorLaw::kSingle, AnchorLaw::kTensor}) {
    const AnchorBlock b = a.make(law);
    EXPECT_TRUE(b.conservative());
    test::expect_derivatives_match_finite_differences(b, 3, x, 1e-6, 1e-7);
  }
}

TEST(AnchorBlock, BlendHessianIsTheSymmetricPartOfItsForceJacobian) {
  const TwoAnchors a;
  const AnchorBlock b = a.make(AnchorLaw::kBlend);
  EXPECT_FALSE(b.conservative());
  VecX x = a.rest;
  x += (VecX(6) << 1e-3, -2e-3, 3e-3, 2e-3, 1e-3, -1e-3).finished();
  const MatX j = test::fd_jacobian([&](const VecX& y) { return test::block_gradient(b, y); }, x, 1e-7);
  const MatX sym = 0.5 * (j + j.transpose());
  EXPECT_LT((test::block_hessian(b, 3, x) - sym).norm(), 1e-6 * sym.norm());
  EXPECT_GT((j - j.transpose()).norm(), 1e-3 * j.norm());  // really not a potential force
}

}  // namespace
}  // namespace hooke::surface
