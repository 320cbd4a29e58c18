// Gradient and Hessian of the FEM block against finite differences of its energy, for every law and
// element kind; invariance of the nonlinear laws under rigid rotation.
#include <gtest/gtest.h>

#include <hooke/core/symmetric_eigen.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/model/model.hpp>
#include <random>
#include <support/block_checks.hpp>
#include <support/meshes.hpp>

namespace hooke::fem {
namespace {

using material::Law;

struct Case {
  Law law;
  mesh::ElementKind kind;
};

class ElasticBlockDerivatives : public ::testing::TestWithParam<Case> {};

TEST_P(ElasticBlockDerivatives, MatchFiniteDifferences) {
  const mesh::Mesh m = test::irregular_mesh(GetParam().kind, 3, 0.2);
  const ElasticBlock block(m, {material::Material{GetParam().law, 14630.0, 0.3, material::Plane::kStress, 0.01}});
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  VecX x = test::flat_positions(m);
  for (Eigen::Index i = 0; i < x.size(); ++i) x(i) += 0.0015 * u(rng);  // ~5-10 % strains
  test::expect_derivatives_match_finite_differences(block, m.dim(), x, 1e-7, 1e-6);
}

TEST_P(ElasticBlockDerivatives, ProjectedHessianIsPositiveSemiDefinite) {
  const mesh::Mesh m = test::irregular_mesh(GetParam().kind, 3, 0.2);
  const ElasticBlock block(m, {material::Material{GetParam().law, 1000.0, 0.3}});
  VecX x = test::flat_positions(m);
  x *= 0.8;  // a strong uniform compression makes StVK indefinite
  const SparseMatrix h = model::block_hessian(block, m.dim(), x, true);
  const VecX eig = symmetric_eigenvalues(MatX(h));
  EXPECT_GT(eig.minCoeff(), -1e-10 * eig.maxCoeff());
}

INSTANTIATE_TEST_SUITE_P(
    LawsAndElements, ElasticBlockDerivatives,
    ::testing::Values(Case{Law::kLinear, mesh::ElementKind::kTriangle}, Case{Law::kStVK, mesh::ElementKind::kTriangle},
                      Case{Law::kNeoHookean, mesh::ElementKind::kTriangle},
                      Case{Law::kLinear, mesh::ElementKind::kQuad}, Case{Law::kStVK, mesh::ElementKind::kQuad},
                      Case{Law::kNeoHookean, mesh::ElementKind::kQuad}, Case{Law::kLinear, mesh::ElementKind::kTet},
                      Case{Law::kStVK, mesh::ElementKind::kTet}, Case{Law::kNeoHookean, mesh::ElementKind::kTet}),
    [](const auto& param_info) {
      return std::string(material::law_name(param_info.param.law)) + "_" +
             std::string(mesh::element_kind_name(param_info.param.kind));
    });

TEST(ElasticBlock, NonlinearEnergyInvariantUnderRigidRotation) {
  const mesh::Mesh m = test::irregular_mesh(mesh::ElementKind::kTet, 3, 0.2);
  const Mat3 r = test::random_rotation();
  VecX x = test::flat_positions(m);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (Eigen::Index i = 0; i < x.size(); ++i) x(i) += 0.001 * u(rng);
  VecX xr = x;
  for (int i = 0; i < m.node_count(); ++i) xr.segment<3>(3 * i) = r * x.segment<3>(3 * i) + Vec3(0.1, -0.2, 0.3);
  for (Law law : {Law::kStVK, Law::kNeoHookean}) {
    const ElasticBlock block(m, {material::Material{law, 1000.0, 0.3}});
    EXPECT_NEAR(block.energy(xr), block.energy(x), 1e-10 * block.energy(x));
  }
}

}  // namespace
}  // namespace hooke::fem
