// The any-nu models (docs/methods/any_nu.md): springs carry what a spring network can (a nu = 1/4 material of
// modulus E_s), a volume term per tet carries lambda_V = lambda - mu; each checked against independently assembled
// tet4 matrices, against the Lloyd methods they reduce to, and against the FEM on the meshes of issue 15's table.
#include <gtest/gtest.h>

#include <cmath>
#include <hooke/calibrate/cauchy_split.hpp>
#include <hooke/calibrate/definiteness.hpp>
#include <hooke/calibrate/method.hpp>
#include <hooke/calibrate/stiffness_fit.hpp>
#include <hooke/experiments/compare.hpp>
#include <hooke/fem/tet4.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/springs/tet_volume_block.hpp>
#include <iostream>

namespace hooke::calibrate {
namespace {

using material::Law;
using material::Material;

mesh::Mesh one_tet(const Eigen::Matrix<double, 4, 3>& p) {
  RowMatXi t(1, 4);
  t << 0, 1, 2, 3;
  return mesh::make_mesh(mesh::ElementKind::kTet, RowMatX(p), t, "one tet");
}

Eigen::Matrix<double, 4, 3> irregular_corners() {
  Eigen::Matrix<double, 4, 3> p;
  p << 0.0, 0.0, 0.0, 0.013, 0.001, -0.002, 0.004, 0.009, 0.001, 0.003, 0.002, 0.011;
  return p;
}

Eigen::Matrix<double, 4, 3> regular_corners(double l) {
  Eigen::Matrix<double, 4, 3> p;
  p << 0, 0, 0, l, 0, 0, l / 2, l * std::sqrt(3.0) / 2, 0, l / 2, l * std::sqrt(3.0) / 6, l * std::sqrt(2.0 / 3.0);
  return p;
}

// Hessian at rest of a model's volume terms alone (N/m).
Mat12 volume_hessian(const mesh::Mesh& m, const SpringModel& s) {
  const springs::TetVolumeBlock block(s.volume_tets, s.volume_stiffness, s.rest_volume);
  model::Model model(3, Eigen::Map<const VecX>(m.nodes.data(), m.nodes.size()));
  model.add(std::make_unique<springs::TetVolumeBlock>(block));
  return Mat12(MatX(model.hessian(model.rest_positions())));
}

TEST(CauchySplit, CarriesLambdaAndMuAndIsContinuousAtOneQuarter) {
  for (double nu : {0.25, 0.3, 0.45, 0.49}) {
    const Material mat{Law::kLinear, 14630.0, nu};
    const material::Lame l = material::lame(mat.youngs_modulus, nu);
    const CauchySplit s = cauchy_split(mat);
    const material::Lame springs = material::lame(s.spring_youngs_modulus, 0.25);  // what Eq. 12 aims at
    EXPECT_NEAR(springs.mu, l.mu, 1e-12 * l.mu);
    EXPECT_NEAR(springs.lambda + s.volume_lambda, l.lambda, 1e-12 * l.lambda);
  }
  const CauchySplit quarter = cauchy_split({Law::kLinear, 14630.0, 0.25});
  EXPECT_NEAR(quarter.spring_youngs_modulus, 14630.0, 1e-12 * 14630.0);
  EXPECT_NEAR(quarter.volume_lambda, 0.0, 1e-12 * 14630.0);
  const CauchySplit low = cauchy_split({Law::kLinear, 14630.0, 0.1});
  EXPECT_EQ(low.spring_youngs_modulus, 14630.0);
  EXPECT_EQ(low.volume_lambda, 0.0);
  EXPECT_LT(unclamped_cauchy_split({Law::kLinear, 14630.0, 0.1}).volume_lambda, 0.0);
}

// The volume term of one (irregular) tet is the lambda part of the tet4 matrix: K_FEM is linear in (lambda, mu),
// so K_lambda = K_FEM(E, nu) - K_FEM(2 mu, 0) (the same mu, lambda = 0), assembled by fem::tet4_stiffness alone.
TEST(AnyNuTet, VolumeTermEqualsTheFemVolumetricPartOnOneTet) {
  const Eigen::Matrix<double, 4, 3> p = irregular_corners();
  const mesh::Mesh m = one_tet(p);
  for (double nu : {0.3, 0.45, 0.49}) {
    const Material mat{Law::kLinear, 14630.0, nu};
    const material::Lame l = material::lame(mat.youngs_modulus, nu);
    const Mat12 k_lambda = fem::tet4_stiffness(p, mat) - fem::tet4_stiffness(p, {Law::kLinear, 2.0 * l.mu, 0.0});
    const Mat12 expected = (l.lambda - l.mu) / l.lambda * k_lambda;
    const SpringModel s = calibrate(m, {mat}, Method::kAnyNuTet);
    ASSERT_EQ(s.volume_tets.rows(), 1);
    const Mat12 got = volume_hessian(m, s);
    EXPECT_LT((got - expected).norm(), 1e-12 * expected.norm()) << "nu = " << nu;
    // The rigid motions are in its null space, as in the FEM matrix.
    Eigen::Matrix<double, 12, 1> shift;
    for (int a = 0; a < 4; ++a) shift.segment<3>(3 * a) = Eigen::Vector3d(0.3, -0.2, 0.7);
    EXPECT_LT((got * shift).norm(), 1e-12 * got.norm() * shift.norm());
  }
}

// Exactness kept: at nu = 1/4 and below, any-nu-tet is lloyd-tet (Eq. 12-13), without volume terms; above, its springs
// are lloyd-tet's scaled by E_s / E.
TEST(AnyNuTet, ReducesToLloydTetAtOneQuarterAndBelow) {
  const mesh::Mesh m = io::read_mesh(HOOKE_MESH_DATA "/cylinder.msh");
  for (double nu : {0.0, 0.1, 0.25}) {
    const Material mat{Law::kLinear, 14630.0, nu};
    const SpringModel a = calibrate(m, {mat}, Method::kAnyNuTet), b = calibrate(m, {mat}, Method::kLloydTet);
    EXPECT_EQ(a.pairs, b.pairs);
    EXPECT_LT((a.stiffness - b.stiffness).norm(), 1e-14 * b.stiffness.norm()) << "nu = " << nu;
    EXPECT_EQ(a.volume_tets.rows(), 0) << "nu = " << nu;
  }
  const Material mat{Law::kLinear, 14630.0, 0.45};
  const SpringModel a = calibrate(m, {mat}, Method::kAnyNuTet), b = calibrate(m, {mat}, Method::kLloydTet);
  const double ratio = cauchy_split(mat).spring_youngs_modulus / 14630.0;
  EXPECT_LT((a.stiffness - ratio * b.stiffness).norm(), 1e-14 * a.stiffness.norm());
  ASSERT_EQ(a.volume_tets.rows(), m.element_count());
  for (int t = 0; t < m.element_count(); ++t)
    EXPECT_NEAR(a.volume_stiffness(t), cauchy_split(mat).volume_lambda * mesh::element_measure(m, t),
                1e-12 * std::abs(a.volume_stiffness(t)));
}

// Why the literal per-element fit fails away from nu = 1/4: a spring network's tensor is fully symmetric, and on a
// regular tet the Frobenius fit at nu equals the fit at nu = 1/4 with mu' = (lambda + 2 mu)/3 (the full
// symmetrisation), 17 times the material's mu at nu = 0.49.
TEST(StiffnessFit, LiteralFitIsTheFullSymmetrisation) {
  const mesh::Mesh m = one_tet(regular_corners(0.01));
  for (double nu : {0.0, 0.45, 0.49}) {
    const Material mat{Law::kLinear, 14630.0, nu};
    const material::Lame l = material::lame(mat.youngs_modulus, nu);
    const double mu_sym = (l.lambda + 2.0 * l.mu) / 3.0;
    const SpringModel literal = stiffness_fit(m, {mat}, {.network_target = false});
    const SpringModel sym = stiffness_fit(m, {{Law::kLinear, 2.5 * mu_sym, 0.25}}, {.network_target = false});
    std::cout << "[regular tet] nu = " << nu << ": literal fit k / (l E) = " << literal.stiffness(0) / (0.01 * 14630.0)
              << ", symmetrised mu' / mu = " << mu_sym / l.mu << "\n";
    EXPECT_LT((literal.stiffness - sym.stiffness).norm(), 1e-9 * sym.stiffness.norm()) << "nu = " << nu;
  }
}

// stiffness-fit-volume: springs fitted at (E_s, 1/4) and scaled, volume terms exactly lambda_V V0; at nu = 1/4 it is
// stiffness-fit.
TEST(StiffnessFitVolume, ExactVolumetricTermAndStiffnessFitAtOneQuarter) {
  const mesh::Mesh m = io::read_mesh(HOOKE_MESH_DATA "/cylinder.msh");
  const Material quarter{Law::kLinear, 14630.0, 0.25};
  const SpringModel a = calibrate(m, {quarter}, Method::kStiffnessFitVolume),
                    b = calibrate(m, {quarter}, Method::kStiffnessFit);
  EXPECT_LT((a.stiffness - b.stiffness).norm(), 1e-12 * b.stiffness.norm());
  EXPECT_EQ(a.volume_tets.rows(), 0);
  const Material mat{Law::kLinear, 14630.0, 0.45};
  const SpringModel v = calibrate(m, {mat}, Method::kStiffnessFitVolume);
  const SpringModel springs_at_es =
      stiffness_fit(m, {{Law::kLinear, cauchy_split(mat).spring_youngs_modulus, 0.25}}, {});
  // The same springs up to the one self-weight factor c of stiffness_scale.hpp.
  const double c = v.stiffness.dot(springs_at_es.stiffness) / springs_at_es.stiffness.squaredNorm();
  EXPECT_LT((v.stiffness - c * springs_at_es.stiffness).norm(), 1e-12 * v.stiffness.norm());
  EXPECT_GT(c, 1.0);
  ASSERT_EQ(v.volume_tets.rows(), m.element_count());
  EXPECT_NEAR(v.volume_stiffness(0), cauchy_split(mat).volume_lambda * mesh::element_measure(m, 0),
              1e-12 * v.volume_stiffness(0));
}

// Where negative volume terms would lose definiteness: the unclamped split at nu = 0 on the cylinder with a hole
// leaves tets without a definite share, and its assembled stiffness is indefinite (the clamped static solve finds
// it); at nu = 0.45 (positive terms) every share is definite.
TEST(AnyNuTet, NegativeVolumeTermsLoseDefinitenessBelowOneQuarter) {
  const mesh::Mesh m = io::read_mesh(HOOKE_MESH_DATA "/cylinder_hole.msh");
  const Material zero{Law::kLinear, 14630.0, 0.0};
  SpringModel s =
      calibrate(m, {{Law::kLinear, unclamped_cauchy_split(zero).spring_youngs_modulus, 0.25}}, Method::kLloydTet);
  s.volume_tets = m.elements;
  s.rest_volume.resize(m.element_count());
  s.volume_stiffness.resize(m.element_count());
  for (int t = 0; t < m.element_count(); ++t) {
    s.rest_volume(t) = mesh::element_measure(m, t);
    s.volume_stiffness(t) = unclamped_cauchy_split(zero).volume_lambda * s.rest_volume(t);
  }
  const std::vector<int> bad = tets_without_definite_share(m, s);
  std::cout << "[cylinder_hole, nu = 0, unclamped] " << bad.size() << " of " << m.element_count()
            << " tets without a definite share\n";
  EXPECT_GT(bad.size(), 0u);
  experiments::CompareOptions o;
  o.strain = 0.001;
  const experiments::Comparison c = experiments::compare_model(m, {zero}, s, o);
  EXPECT_NE(c.spring_report.status, solve::SolveStatus::kConverged);

  const SpringModel positive = calibrate(m, {{Law::kLinear, 14630.0, 0.45}}, Method::kAnyNuTet);
  EXPECT_TRUE(tets_without_definite_share(m, positive).empty());
}

// Issue 15's targets in the linear regime (relative L2 node error against the linear FEM, 0.1 % strain): <= 0.15 at
// nu in [0.25, 0.49] and <= 0.20 below, on the cylinder with a hole (stretch) and the cone (shear).
class AnyNuAgainstFem : public testing::TestWithParam<double> {};

TEST_P(AnyNuAgainstFem, WithinTheTargetsOnBothMeshes) {
  const double nu = GetParam();
  const Material mat{Law::kLinear, 14630.0, nu};
  experiments::CompareOptions o;
  o.method = Method::kAnyNuTet;
  o.strain = 0.001;
  const std::pair<const char*, model::LoadKind> cases[] = {{"/cylinder_hole.msh", model::LoadKind::kStretch},
                                                           {"/cone.msh", model::LoadKind::kShear}};
  for (const auto& [file, load] : cases) {
    o.load = load;
    const experiments::Comparison c =
        experiments::compare(io::read_mesh(std::string(HOOKE_MESH_DATA) + file), {mat}, o);
    ASSERT_EQ(c.spring_report.status, solve::SolveStatus::kConverged) << c.spring_report.message;
    std::cout << "[any-nu-tet] " << file << " nu = " << nu << ": relative L2 " << c.relative_l2 << "\n";
    EXPECT_LT(c.relative_l2, nu >= 0.25 ? 0.15 : 0.20) << file << " nu = " << nu;
  }
}

INSTANTIATE_TEST_SUITE_P(Nu, AnyNuAgainstFem, testing::Values(0.0, 0.25, 0.45, 0.49));

}  // namespace
}  // namespace hooke::calibrate
