// any-nu-triangle (issue 15 item 1, triangles) against independent derivations: the area block's gradient and
// Hessian against central finite differences of its energy and gradient; its Hessian at rest equal to the lambda part
// of the CST matrix, K_CST(E, nu) - K_CST(2 mu, 0) (plane strain: the same mu with lambda = 0), scaled to
// lambda* - mu; the split carrying mu and lambda*; lloyd-triangle recovered where lambda* <= mu; the model file round
// trip of area terms; and the accuracy against the linear FEM on the committed rectangle in plane strain.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <hooke/calibrate/cauchy_split.hpp>
#include <hooke/calibrate/method.hpp>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/calibrate/model_file.hpp>
#include <hooke/experiments/compare.hpp>
#include <hooke/fem/cst.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/springs/triangle_area_block.hpp>
#include <iostream>
#include <support/block_checks.hpp>

namespace hooke::calibrate {
namespace {

using material::Law;
using material::Material;
using material::Plane;
using Mat6 = Eigen::Matrix<double, 6, 6>;

Eigen::Matrix<double, 3, 2> irregular_triangle() {
  Eigen::Matrix<double, 3, 2> p;
  p << 0.0, 0.0, 0.013, 0.002, 0.004, 0.009;
  return p;
}

TEST(TriangleAreaBlock, GradientAndHessianMatchFiniteDifferences) {
  RowMatXi t(1, 3);
  t << 0, 1, 2;
  const Eigen::Matrix<double, 3, 2> p = irregular_triangle();
  const double a0 = 0.5 * ((p(1, 0) - p(0, 0)) * (p(2, 1) - p(0, 1)) - (p(1, 1) - p(0, 1)) * (p(2, 0) - p(0, 0)));
  model::Model model(2, Eigen::Map<const VecX>(RowMatX(p).data(), 6));
  model.add(std::make_unique<springs::TriangleAreaBlock>(t, VecX::Constant(1, 3.7), VecX::Constant(1, a0)));
  VecX x = model.rest_positions();
  x += 0.001 * VecX::LinSpaced(6, -1.0, 1.3).cwiseProduct(VecX::Constant(6, 1.0) + VecX::LinSpaced(6, 0.0, 0.5));
  const VecX g = model.gradient(x);
  const MatX h(model.hessian(x));
  const double eps = 1e-7;
  for (int i = 0; i < 6; ++i) {
    VecX xp = x, xm = x;
    xp(i) += eps;
    xm(i) -= eps;
    EXPECT_NEAR(g(i), (model.energy(xp) - model.energy(xm)) / (2 * eps), 1e-6 * g.norm()) << i;
    const VecX column = (model.gradient(xp) - model.gradient(xm)) / (2 * eps);
    EXPECT_LT((h.col(i) - column).norm(), 1e-6 * h.norm()) << i;
  }
  EXPECT_LT((h - h.transpose()).norm(), 1e-12 * h.norm());
  test::expect_fused_energy_and_gradient(*model.blocks()[0], x);
}

// K_CST is linear in (lambda*, mu): K_lambda = K_CST(E, nu) - K_CST(2 mu, 0) in plane strain (lambda* = lambda).
TEST(AnyNuTriangle, AreaTermEqualsTheCstVolumetricPart) {
  const Eigen::Matrix<double, 3, 2> p = irregular_triangle();
  RowMatXi t(1, 3);
  t << 0, 1, 2;
  const mesh::Mesh m = mesh::make_mesh(mesh::ElementKind::kTriangle, RowMatX(p), t, "one triangle");
  for (double nu : {0.3, 0.45, 0.49}) {
    Material mat{Law::kLinear, 14630.0, nu, Plane::kStrain, 0.002};
    const material::Lame l = material::lame(mat, 2);
    Material shear_only = mat;
    shear_only.youngs_modulus = 2.0 * l.mu;
    shear_only.poisson_ratio = 0.0;
    const Mat6 k_lambda = fem::cst_stiffness(p, mat) - fem::cst_stiffness(p, shear_only);
    const Mat6 expected = (l.lambda - l.mu) / l.lambda * k_lambda;
    const SpringModel s = calibrate(m, {mat}, Method::kAnyNuTriangle);
    ASSERT_EQ(s.volume_tets.rows(), 1);
    ASSERT_EQ(s.volume_tets.cols(), 3);
    model::Model model(2, Eigen::Map<const VecX>(m.nodes.data(), m.nodes.size()));
    model.add(std::make_unique<springs::TriangleAreaBlock>(s.volume_tets, s.volume_stiffness, s.rest_volume));
    const Mat6 got = Mat6(MatX(model.hessian(model.rest_positions())));
    EXPECT_LT((got - expected).norm(), 1e-12 * expected.norm()) << "nu = " << nu;
  }
}

TEST(CauchySplit2d, CarriesMuAndLambdaStarAboveTheThreshold) {
  for (Plane plane : {Plane::kStress, Plane::kStrain})
    for (double nu : {0.34, 0.4, 0.49}) {
      const Material mat{Law::kLinear, 14630.0, nu, plane, 0.001};
      const material::Lame l = material::lame(mat, 2);
      const CauchySplit s = cauchy_split_2d(mat);
      // Eq. 9 aims at the nu = 1/3 plane-stress material of modulus E_s: mu = 3 E_s / 8, lambda* = mu.
      EXPECT_NEAR(3.0 * s.spring_youngs_modulus / 8.0, l.mu, 1e-12 * l.mu);
      EXPECT_NEAR(l.mu + s.volume_lambda, l.lambda, 1e-12 * l.lambda);
    }
  const CauchySplit third = cauchy_split_2d({Law::kLinear, 14630.0, 1.0 / 3.0, Plane::kStress, 0.001});
  EXPECT_NEAR(third.spring_youngs_modulus, 14630.0, 1e-9 * 14630.0);  // continuous in plane stress
  EXPECT_NEAR(third.volume_lambda, 0.0, 1e-9 * 14630.0);
}

TEST(AnyNuTriangle, IsLloydTriangleWhereSpringsSuffice) {
  const mesh::Mesh m = io::read_mesh(HOOKE_MESH_DATA "/rectangle_tri.msh");
  for (double nu : {0.0, 0.2, 1.0 / 3.0}) {
    const Material mat{Law::kLinear, 14630.0, nu, Plane::kStress, 0.001};
    const SpringModel a = calibrate(m, {mat}, Method::kAnyNuTriangle), b = calibrate(m, {mat}, Method::kLloydTriangle);
    EXPECT_EQ(a.pairs, b.pairs);
    EXPECT_LT((a.stiffness - b.stiffness).norm(), 1e-9 * b.stiffness.norm()) << "nu = " << nu;
    EXPECT_EQ(a.volume_tets.rows(), 0);
  }
}

TEST(AnyNuTriangle, AreaTermsSurviveTheModelFile) {
  ModelOptions o;
  o.method = "any-nu-triangle";
  const CalibratedModel written = calibrate_model(io::read_mesh(HOOKE_MESH_DATA "/rectangle_tri.msh"),
                                                  {Law::kLinear, 14630.0, 0.45, Plane::kStrain, 0.001}, o);
  ASSERT_GT(written.springs.volume_tets.rows(), 0);
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "hooke_any_nu_triangle.json";
  write_model(path, written);
  const CalibratedModel read = read_model(path);
  EXPECT_EQ(read.springs.volume_tets, written.springs.volume_tets);
  EXPECT_EQ(read.springs.volume_stiffness, written.springs.volume_stiffness);
  EXPECT_EQ(read.springs.rest_volume, written.springs.rest_volume);
}

// In plane strain, where lambda* grows without bound as nu -> 1/2, springs alone (lloyd-triangle) are 0.67 off in
// stretch at nu = 0.49 (measured); the area terms bring the committed rectangle within 0.15 at nu >= 0.3.
TEST(AnyNuTriangle, FollowsTheFemInPlaneStrain) {
  const mesh::Mesh m = io::read_mesh(HOOKE_MESH_DATA "/rectangle_tri.msh");
  for (double nu : {0.3, 0.45, 0.49})
    for (model::LoadKind load : {model::LoadKind::kStretch, model::LoadKind::kShear}) {
      const Material mat{Law::kLinear, 14630.0, nu, Plane::kStrain, 0.001};
      experiments::CompareOptions o;
      o.load = load;
      o.strain = 0.001;
      o.method = Method::kAnyNuTriangle;
      const experiments::Comparison any = experiments::compare(m, {mat}, o);
      o.method = Method::kLloydTriangle;
      const experiments::Comparison lloyd = experiments::compare(m, {mat}, o);
      std::cout << "[rectangle_tri, plane strain, nu = " << nu << "] any-nu-triangle " << any.relative_l2
                << ", lloyd-triangle " << lloyd.relative_l2 << "\n";
      EXPECT_LT(any.relative_l2, 0.15) << "nu = " << nu;
      EXPECT_LT(any.relative_l2, lloyd.relative_l2) << "nu = " << nu;
    }
}

}  // namespace
}  // namespace hooke::calibrate
