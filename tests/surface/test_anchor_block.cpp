// Anchors (Arnab & Raja Eq. 2 and the K_E / K_G blend): the stiffness is K_E along the normal and K_G across
// it; forces are derivatives of the energy where one exists; the blend's Hessian is the symmetric part of its
// force Jacobian. At a crease (normal_cone.hpp) the blend sees both faces' normals.
#include <gtest/gtest.h>

#include <hooke/mesh/generators.hpp>
#include <hooke/surface/anchor_block.hpp>
#include <hooke/surface/discretisation.hpp>
#include <hooke/surface/normal_cone.hpp>
#include <support/block_checks.hpp>

namespace hooke::surface {
namespace {

struct TwoAnchors {
  VecX rest = (VecX(6) << 0.0, 0.0, 0.0, 1.0, 0.5, -0.2).finished();
  RowMatX normals = (RowMatX(2, 3) << 0.0, 0.0, 1.0, 0.6, 0.0, 0.8).finished();
  VecX k_e = (VecX(2) << 300.0, 200.0).finished();
  VecX k_g = (VecX(2) << 100.0, 50.0).finished();
  AnchorBlock make(AnchorLaw law) const {
    RowMatX cones(2, 6);
    for (int i = 0; i < 2; ++i) cones.row(i) = smooth_cone(normals.row(i).transpose());
    return AnchorBlock(rest, cones, k_e, k_g, law);
  }
};

// A node on a right-angled crease between the faces of normals n1 = z and n2 = x (a cube's edge along y), and a
// smooth node beside it.
struct CreaseAnchors {
  VecX rest = (VecX(6) << 0.0, 0.0, 0.0, 1.0, 0.5, -0.2).finished();
  Vec3 n1 = Vec3::UnitZ(), n2 = Vec3::UnitX();
  VecX k_e = (VecX(2) << 300.0, 200.0).finished();
  VecX k_g = (VecX(2) << 100.0, 50.0).finished();
  AnchorBlock make(AnchorLaw law) const {
    RowMatX cones(2, 6);
    cones.row(0) = pack_cone(n1 * n1.transpose() + n2 * n2.transpose());
    cones.row(1) = smooth_cone(Vec3(0.6, 0.0, 0.8));
    return AnchorBlock(rest, cones, k_e, k_g, law);
  }
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

// The averaged normal of a crease node, (n1 + n2) / sqrt(2), is neither face's: the paper's blend read with it
// would give a push normal to either face only (K_E + K_G) / 2 + (K_E - K_G) (|cos 45 deg| - 1/2). With the
// crease's cone both face normals are normal directions (K_E), the edge's direction is tangential (K_G).
TEST(AnchorBlock, AtACreaseBothFaceNormalsAreNormalDirections) {
  const CreaseAnchors a;
  for (AnchorLaw law : {AnchorLaw::kBlend, AnchorLaw::kTensor}) {
    const AnchorBlock b = a.make(law);
    EXPECT_NEAR(b.stiffness_along(0, a.n1), 300.0, 1e-12) << anchor_law_name(law);
    EXPECT_NEAR(b.stiffness_along(0, -a.n2), 300.0, 1e-12) << anchor_law_name(law);
    EXPECT_NEAR(b.stiffness_along(0, (a.n1 - a.n2).normalized()), 300.0, 1e-12) << anchor_law_name(law);
    EXPECT_NEAR(b.stiffness_along(0, Vec3::UnitY()), 100.0, 1e-12) << anchor_law_name(law);
    for (double s : {1e-3, -2e-3}) {  // and the force is K_E d for a displacement along a face normal
      VecX x = a.rest;
      x.segment<3>(0) += s * a.n2;
      const VecX g = test::block_gradient(b, x);
      EXPECT_LT((g.segment<3>(0) - 300.0 * s * a.n2).norm(), 1e-12) << anchor_law_name(law);
    }
  }
}

TEST(AnchorBlock, CreaseBlendHessianIsTheSymmetricPartOfItsForceJacobian) {
  const CreaseAnchors a;
  const AnchorBlock b = a.make(AnchorLaw::kBlend);
  VecX x = a.rest;
  x += (VecX(6) << 1e-3, -2e-3, 3e-3, 2e-3, 1e-3, -1e-3).finished();
  const MatX j = test::fd_jacobian([&](const VecX& y) { return test::block_gradient(b, y); }, x, 1e-7);
  const MatX sym = 0.5 * (j + j.transpose());
  EXPECT_LT((test::block_hessian(b, 3, x) - sym).norm(), 1e-6 * sym.norm());
  test::expect_derivatives_match_finite_differences(a.make(AnchorLaw::kTensor), 3, x, 1e-6, 1e-7);
}

// On a cube: a face node's cone is N N^T, an edge node's the projector onto its two faces' normals, a corner's
// the identity. On a sphere fine enough to be smooth, every cone is N N^T to the last bit.
TEST(NormalCone, CubeEdgesAndCornersSeeTheirFacesAndSmoothSurfacesTheNormal) {
  const mesh::Mesh cube = mesh::cube_surface(4, 2.0);
  const VecX x = mesh::flat_positions(cube);
  const RowMatX normals = node_normals(cube.elements, x);
  const RowMatX cones = node_normal_cones(cube.elements, x, normals);
  int counts[4] = {0, 0, 0, 0};
  for (int i = 0; i < cube.node_count(); ++i) {
    const Vec3 p = cube.nodes.row(i).transpose();
    Mat3 expected = Mat3::Zero();
    int faces = 0;
    for (int k = 0; k < 3; ++k)
      if (p(k) < 1e-12 || p(k) > 2.0 - 1e-12) {
        expected(k, k) = 1.0;  // the face normal e_k, either sign
        ++faces;
      }
    ++counts[faces];
    EXPECT_LT((unpack_cone(cones.row(i)) - expected).norm(), 1e-12) << "node " << i << " on " << faces << " faces";
  }
  EXPECT_EQ(counts[1], 6 * 9);
  EXPECT_EQ(counts[2], 12 * 3);
  EXPECT_EQ(counts[3], 8);
  const mesh::Mesh sphere = mesh::uv_sphere_surface(16, 24, 0.05);
  const VecX xs = mesh::flat_positions(sphere);
  const RowMatX ns = node_normals(sphere.elements, xs);
  const RowMatX cs = node_normal_cones(sphere.elements, xs, ns);
  for (int i = 0; i < sphere.node_count(); ++i) EXPECT_TRUE(cs.row(i) == smooth_cone(ns.row(i).transpose())) << i;
}

TEST(NormalCone, PackAndUnpackAreInverse) {
  Mat3 p;
  p << 0.5, 0.1, -0.2, 0.1, 0.7, 0.3, -0.2, 0.3, 0.9;
  EXPECT_TRUE(unpack_cone(pack_cone(p)) == p);
  EXPECT_LT(
      (unpack_cone(smooth_cone(Vec3(0.6, 0.0, 0.8))) - Vec3(0.6, 0.0, 0.8) * Vec3(0.6, 0.0, 0.8).transpose()).norm(),
      1e-16);
}

}  // namespace
}  // namespace hooke::surface
