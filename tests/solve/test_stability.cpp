#include <gtest/gtest.h>

#include <support/matrices.hpp>

#include <cmath>
#include <hooke/solve/stability.hpp>

namespace hooke::solve {
namespace {

class SmallestEigenvalue : public ::testing::TestWithParam<int> {};

TEST_P(SmallestEigenvalue, MatchesAnalyticValuePositiveAndNegative) {
  const int n = GetParam();
  for (double s : {0.05, -0.02}) {
    const double exact = s + 2.0 - 2.0 * std::cos(M_PI / (n + 1));
    EXPECT_NEAR(smallest_eigenvalue(test::shifted_laplacian(n, s)), exact, 1e-6 * std::max(1e-3, std::abs(exact)))
        << "n = " << n << ", s = " << s;
  }
}

INSTANTIATE_TEST_SUITE_P(DenseAndIterative, SmallestEigenvalue, ::testing::Values(50, 2000));

}  // namespace
}  // namespace hooke::solve
