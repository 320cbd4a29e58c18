#include <gtest/gtest.h>

#include <cmath>
#include <hooke/solve/stability.hpp>

namespace hooke::solve {
namespace {

// 1D Laplacian tridiag(-1, 2 + s, -1): eigenvalues s + 2 - 2 cos(k pi / (n + 1)).
SparseMatrix shifted_laplacian(int n, double s) {
  std::vector<Triplet> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0 + s);
    if (i + 1 < n) {
      t.emplace_back(i, i + 1, -1.0);
      t.emplace_back(i + 1, i, -1.0);
    }
  }
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

class SmallestEigenvalue : public ::testing::TestWithParam<int> {};

TEST_P(SmallestEigenvalue, MatchesAnalyticValuePositiveAndNegative) {
  const int n = GetParam();
  for (double s : {0.05, -0.02}) {
    const double exact = s + 2.0 - 2.0 * std::cos(M_PI / (n + 1));
    EXPECT_NEAR(smallest_eigenvalue(shifted_laplacian(n, s)), exact, 1e-6 * std::max(1e-3, std::abs(exact)))
        << "n = " << n << ", s = " << s;
  }
}

INSTANTIATE_TEST_SUITE_P(DenseAndIterative, SmallestEigenvalue, ::testing::Values(50, 2000));

}  // namespace
}  // namespace hooke::solve
