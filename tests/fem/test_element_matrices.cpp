// Closed-form element matrices (Lloyd Eq. 3-5, Q4 with B matrices, App. B) against the hyperelastic kernel
// (dP/dF contracted with shape gradients), an independent derivation; rigid modes; symmetry; PSD.
#include <gtest/gtest.h>

#include <hooke/core/error.hpp>
#include <hooke/core/symmetric_eigen.hpp>
#include <hooke/fem/cst.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/fem/quad4.hpp>
#include <hooke/fem/tet4.hpp>
#include <hooke/mesh/validate.hpp>
#include <random>
#include <support/meshes.hpp>

namespace hooke::fem {
namespace {

using material::Law;
using material::Material;
using material::Plane;

MatX kernel_stiffness(const mesh::Mesh& m, const Material& mat) {
  const ElasticBlock block(m, {mat});
  double e = 0;
  VecX g;
  MatX h;
  block.element_derivatives(test::flat_positions(m), 0, e, g, h);
  return h;
}

mesh::Mesh single(mesh::ElementKind kind, const RowMatX& nodes) {
  RowMatXi elems(1, nodes.rows());
  for (int k = 0; k < nodes.rows(); ++k) elems(0, k) = k;
  return mesh::make_mesh(kind, nodes, elems, "test element");
}

// Checks symmetry, PSD and a null space of exactly `rigid` dimensions containing the rigid modes.
void expect_rigid_null_space(const MatX& k, int dim, int rigid) {
  EXPECT_LT((k - k.transpose()).norm(), 1e-12 * k.norm());
  const VecX ev = symmetric_eigenvalues(k);
  const double scale = ev.maxCoeff();
  for (int i = 0; i < rigid; ++i) EXPECT_NEAR(ev(i), 0.0, 1e-10 * scale) << "eigenvalue " << i;
  EXPECT_GT(ev(rigid), 1e-6 * scale) << "null space larger than the rigid modes";
  // Translations and infinitesimal rotations are annihilated.
  const int n = static_cast<int>(k.rows()) / dim;
  VecX mode(k.rows());
  for (int axis = 0; axis < dim; ++axis) {
    mode.setZero();
    for (int a = 0; a < n; ++a) mode(dim * a + axis) = 1.0;
    EXPECT_LT((k * mode).norm(), 1e-10 * scale);
  }
}

Eigen::Matrix<double, 3, 2> random_triangle(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  Eigen::Matrix<double, 3, 2> p;
  p << 0 + u(rng), 0 + u(rng), 1 + u(rng), 0 + u(rng), 0.4 + u(rng), 1 + u(rng);
  return p * 0.02;
}

TEST(CstStiffness, EqualsHyperelasticKernelPlaneStressAndStrain) {
  std::mt19937 rng(1);
  for (Plane plane : {Plane::kStress, Plane::kStrain})
    for (int trial = 0; trial < 10; ++trial) {
      const Eigen::Matrix<double, 3, 2> p = random_triangle(rng);
      const Material mat{Law::kLinear, 14630.0, 0.1 + 0.03 * trial, plane, 0.002};
      const Mat6 k = cst_stiffness(p, mat);
      const MatX ref = kernel_stiffness(single(mesh::ElementKind::kTriangle, p), mat);
      EXPECT_LT((k - ref).norm(), 1e-11 * k.norm());
      expect_rigid_null_space(k, 2, 3);
    }
}

TEST(CstStiffness, BlocksSymmetricOnlyAtNuOneThirdForEquilateral) {
  // Lloyd Sec. 3.3: the 2x2 blocks K_ij become symmetric at nu = 1/3 (they never are for nu != 1/3).
  Eigen::Matrix<double, 3, 2> p;
  p << 0, 0, 1, 0, 0.5, std::sqrt(3.0) / 2;
  auto asym = [&](double nu) {
    const Mat6 k = cst_stiffness(p, Material{Law::kLinear, 1.0, nu});
    double worst = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) worst = std::max(worst, std::abs(k(2 * i, 2 * j + 1) - k(2 * i + 1, 2 * j)));
    return worst;
  };
  EXPECT_LT(asym(1.0 / 3.0), 1e-14);
  EXPECT_GT(asym(0.25), 1e-3);
}

TEST(Quad4Stiffness, EqualsHyperelasticKernelAndHasRigidNullSpace) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-0.15, 0.15);
  for (int trial = 0; trial < 10; ++trial) {
    Eigen::Matrix<double, 4, 2> p;
    p << 0 + u(rng), 0 + u(rng), 1 + u(rng), 0 + u(rng), 1 + u(rng), 1 + u(rng), 0 + u(rng), 1 + u(rng);
    const Material mat{Law::kLinear, 14630.0, 0.3, Plane::kStress, 0.01};
    const Mat8 k = quad4_stiffness(p, mat);
    const MatX ref = kernel_stiffness(single(mesh::ElementKind::kQuad, p), mat);
    EXPECT_LT((k - ref).norm(), 1e-11 * k.norm());
    expect_rigid_null_space(k, 2, 3);
  }
}

TEST(Quad4Stiffness, RectangleMatchesClosedFormDiagonal) {
  // For an a x b rectangle under plane stress, K_11 = E t / (1 - nu^2) (b/(3a) + (1 - nu) a/(6b)) (Logan).
  const double a = 2.0, b = 1.0, e = 100.0, nu = 0.3, t = 0.5;
  Eigen::Matrix<double, 4, 2> p;
  p << 0, 0, a, 0, a, b, 0, b;
  const Mat8 k = quad4_stiffness(p, Material{Law::kLinear, e, nu, Plane::kStress, t});
  EXPECT_NEAR(k(0, 0), e * t / (1 - nu * nu) * (b / (3 * a) + (1 - nu) * a / (6 * b)), 1e-12);
}

TEST(Tet4Stiffness, EqualsHyperelasticKernelAndHasRigidNullSpace) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  for (int trial = 0; trial < 10; ++trial) {
    Eigen::Matrix<double, 4, 3> p;
    p << u(rng), u(rng), u(rng), 1 + u(rng), u(rng), u(rng), u(rng), 1 + u(rng), u(rng), u(rng), u(rng), 1 + u(rng);
    p *= 0.01;
    const Material mat{Law::kLinear, 14630.0, 0.05 + 0.04 * trial};
    const Mat12 k = tet4_stiffness(p, mat);
    const MatX ref = kernel_stiffness(single(mesh::ElementKind::kTet, p), mat);
    EXPECT_LT((k - ref).norm(), 1e-11 * k.norm());
    expect_rigid_null_space(k, 3, 6);
  }
}

TEST(Tet4Stiffness, RejectsInvertedTet) {
  Eigen::Matrix<double, 4, 3> p;
  p << 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1;  // negative orientation
  EXPECT_THROW(tet4_stiffness(p, Material{Law::kLinear, 1.0, 0.3}), InvalidMesh);
}

}  // namespace
}  // namespace hooke::fem
