// The PSD projection (core/detail/psd.hpp) against its definition: the nearest PSD matrix in the Frobenius norm.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <hooke/core/detail/psd.hpp>

namespace {

using Mat12 = Eigen::Matrix<double, 12, 12>;

Mat12 random_symmetric(unsigned seed) {
  std::srand(seed);
  const Mat12 a = Mat12::Random();
  return a + a.transpose();
}

TEST(ProjectToPsd, ZeroesTheNegativeEigenvaluesAndKeepsTheEigenvectors) {
  const Mat12 m = random_symmetric(7);
  Mat12 p = m;
  hooke::detail::project_to_psd(p);
  const Eigen::SelfAdjointEigenSolver<Mat12> before(m), after(p);
  ASSERT_LT(before.eigenvalues().minCoeff(), -0.5);  // the case is not trivial
  EXPECT_GE(after.eigenvalues().minCoeff(), -1e-12);
  EXPECT_LT((p - p.transpose()).norm(), 1e-12);
  // The positive eigenpairs are kept: P v = lambda v for each of them, P v = 0 for the others.
  for (int i = 0; i < 12; ++i) {
    const Eigen::Matrix<double, 12, 1> v = before.eigenvectors().col(i);
    const double lambda = std::max(before.eigenvalues()(i), 0.0);
    EXPECT_LT((p * v - lambda * v).norm(), 1e-11) << "eigenpair " << i;
  }
}

TEST(ProjectToPsd, IsNearerThanAnyOtherPsdMatrixTried) {
  const Mat12 m = random_symmetric(11);
  Mat12 p = m;
  hooke::detail::project_to_psd(p);
  for (unsigned s = 0; s < 50; ++s) {
    const Mat12 b = Mat12::Random();
    const Mat12 other = p + 0.1 * b * b.transpose();  // PSD, as the sum of two PSD matrices
    EXPECT_LE((m - p).norm(), (m - other).norm() + 1e-12);
  }
}

TEST(ProjectToPsd, LeavesAPsdMatrixAndSmallerSizesAlone) {
  const Mat12 a = Mat12::Random();
  const Mat12 psd = a * a.transpose();
  Mat12 p = psd;
  hooke::detail::project_to_psd(p);
  EXPECT_EQ(p, psd);
  Eigen::Matrix<double, 6, 6> small = Eigen::Matrix<double, 6, 6>::Identity();
  small(0, 0) = -2.0;
  hooke::detail::project_to_psd(small);
  Eigen::Matrix<double, 6, 6> expected = Eigen::Matrix<double, 6, 6>::Identity();
  expected(0, 0) = 0.0;
  EXPECT_LT((small - expected).norm(), 1e-14);
}

}  // namespace
