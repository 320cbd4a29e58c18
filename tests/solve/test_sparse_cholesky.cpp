#include <gtest/gtest.h>

#include <hooke/solve/sparse_cholesky.hpp>
#include <random>

namespace hooke::solve {
namespace {

SparseMatrix laplacian_1d(int n, double shift) {
  std::vector<Triplet> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0 + shift);
    if (i + 1 < n) {
      t.emplace_back(i, i + 1, -1.0);
      t.emplace_back(i + 1, i, -1.0);
    }
  }
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

TEST(SparseCholesky, CholmodAndEigenAgree) {
  const SparseMatrix a = laplacian_1d(500, 0.01);
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

TEST(SparseCholesky, ReportsIndefiniteMatrices) {
  const SparseMatrix a = laplacian_1d(200, -0.5);  // eigenvalues 1.5 - 2 cos(...) include negatives
  for (CholeskyBackend b : {CholeskyBackend::kCholmod, CholeskyBackend::kEigen}) {
    SparseCholesky c(b);
    EXPECT_FALSE(c.factorize(a)) << c.backend_name();
  }
}

TEST(SparseCholesky, ReusesAnalysisAcrossValues) {
  SparseCholesky c;
  ASSERT_TRUE(c.factorize(laplacian_1d(100, 0.1)));
  const SparseMatrix a2 = laplacian_1d(100, 1.0);
  ASSERT_TRUE(c.factorize(a2));
  const VecX b = VecX::Ones(100);
  EXPECT_LT((a2 * c.solve(b) - b).norm(), 1e-12);
}

}  // namespace
}  // namespace hooke::solve
