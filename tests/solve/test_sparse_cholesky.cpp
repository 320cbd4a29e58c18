#include <gtest/gtest.h>

#include <support/matrices.hpp>

#include <hooke/solve/sparse_cholesky.hpp>
#include <random>

namespace hooke::solve {
namespace {

TEST(SparseCholesky, CholmodAndEigenAgree) {
  const SparseMatrix a = test::shifted_laplacian(500, 0.01);
  VecX b = VecX::LinSpaced(500, -1.0, 2.0);
  SparseCholesky c(CholeskyBackend::kCholmod), e(CholeskyBackend::kEigen);
  ASSERT_TRUE(c.factorize(a));
  ASSERT_TRUE(e.factorize(a));
  const VecX xc = c.solve(b), xe = e.solve(b);
  EXPECT_LT((a * xc - b).norm(), 1e-10 * b.norm());
  EXPECT_LT((xc - xe).norm(), 1e-9 * xc.norm());
  EXPECT_EQ(c.backend_name(), "cholmod");
  EXPECT_EQ(e.backend_name(), "eigen-ldlt");
}

// kAuto: Eigen's LDL^T for small systems, CHOLMOD from 1 000 unknowns on.
TEST(SparseCholesky, AutoPicksTheBackendBySize) {
  SparseCholesky small, large;
  ASSERT_TRUE(small.factorize(test::shifted_laplacian(500, 0.01)));
  ASSERT_TRUE(large.factorize(test::shifted_laplacian(2000, 0.01)));
  EXPECT_EQ(small.backend_name(), "eigen-ldlt");
  EXPECT_EQ(large.backend_name(), "cholmod");
}

TEST(SparseCholesky, ReportsIndefiniteMatrices) {
  const SparseMatrix a = test::shifted_laplacian(200, -0.5);  // eigenvalues 1.5 - 2 cos(...) include negatives
  for (CholeskyBackend b : {CholeskyBackend::kCholmod, CholeskyBackend::kEigen}) {
    SparseCholesky c(b);
    EXPECT_FALSE(c.factorize(a)) << c.backend_name();
  }
}

TEST(SparseCholesky, ReusesAnalysisAcrossValues) {
  SparseCholesky c;
  ASSERT_TRUE(c.factorize(test::shifted_laplacian(100, 0.1)));
  const SparseMatrix a2 = test::shifted_laplacian(100, 1.0);
  ASSERT_TRUE(c.factorize(a2));
  const VecX b = VecX::Ones(100);
  EXPECT_LT((a2 * c.solve(b) - b).norm(), 1e-12);
}

}  // namespace
}  // namespace hooke::solve
