// The bounded least-squares solver against independent answers: exact enumeration of supports (calibrate's
// fit_nonnegative), scipy.optimize.nnls on a committed problem, and the KKT conditions on larger ones.
#include <gtest/gtest.h>
#include <fstream>
#include <hooke/calibrate/stiffness_fit.hpp>
#include <hooke/core/error.hpp>
#include <hooke/identify/bounded_least_squares.hpp>
#include <limits>
#include <random>

using namespace hooke;
using identify::DenseOperator;
using identify::solve_bounded_least_squares;

namespace {

MatX random_matrix(int rows, int cols, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  MatX a(rows, cols);
  for (int c = 0; c < cols; ++c)
    for (int r = 0; r < rows; ++r) a(r, c) = n(rng) * std::pow(10.0, (c % 4) - 2);  // columns over 4 decades
  return a;
}

VecX random_vector(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> d(0.0, 1.0);
  VecX v(n);
  for (int i = 0; i < n; ++i) v(i) = d(rng);
  return v;
}

// KKT of min |Ax - b|^2/2, x >= l: g = A^T(Ax - b) is 0 where x > l and >= 0 where x = l.
void expect_kkt(const MatX& a, const VecX& b, const VecX& lower, const VecX& x, double tol) {
  const VecX g = a.transpose() * (a * x - b);
  const double scale = (a.transpose() * b).norm();
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    ASSERT_GE(x(j), lower(j));
    const double gj = g(j) / (a.col(j).norm() * scale / a.cols());
    if (x(j) > lower(j))
      EXPECT_NEAR(gj, 0.0, tol) << "free variable " << j;
    else
      EXPECT_GE(gj, -tol) << "variable " << j << " at its bound";
  }
}

}  // namespace

TEST(BoundedLeastSquares, EqualsExhaustiveSupportSearch) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const MatX a = random_matrix(15, 8, seed);
    const VecX b = random_vector(15, 100 + seed);
    std::vector<MatX> bases;
    for (int c = 0; c < a.cols(); ++c) bases.push_back(a.col(c));
    const VecX exact = calibrate::fit_nonnegative(b, bases);
    identify::BoundedLeastSquaresReport report;
    const VecX x = solve_bounded_least_squares(DenseOperator(a), b, VecX::Zero(8), {}, {}, &report);
    EXPECT_TRUE(report.converged) << "seed " << seed;
    for (int j = 0; j < 8; ++j)
      EXPECT_NEAR(x(j) * a.col(j).norm(), exact(j) * a.col(j).norm(), 1e-7 * b.norm()) << "seed " << seed << " x" << j;
    EXPECT_NEAR((a * x - b).norm(), (a * exact - b).norm(), 1e-10 * b.norm());
  }
}

// A target whose unconstrained least-squares solution is non-negative (a positive combination of the bases plus
// noise): fit_nonnegative returns that solution (its shortcut: no subset is better) and the bounded solver agrees.
TEST(BoundedLeastSquares, NonNegativeUnconstrainedSolutionIsTheFit) {
  for (unsigned seed = 1; seed <= 10; ++seed) {
    const MatX a = random_matrix(15, 6, seed);
    const VecX x_true = random_vector(6, 200 + seed).cwiseAbs() + VecX::Constant(6, 0.5);
    const VecX b = a * x_true + 1e-3 * random_vector(15, 300 + seed);
    std::vector<MatX> bases;
    for (int c = 0; c < a.cols(); ++c) bases.push_back(a.col(c));
    double residual = -1.0;
    const VecX fit = calibrate::fit_nonnegative(b, bases, &residual);
    const VecX unconstrained = a.colPivHouseholderQr().solve(b);
    ASSERT_TRUE((unconstrained.array() > 0.0).all()) << "seed " << seed;
    EXPECT_LT((fit - unconstrained).norm(), 1e-8 * unconstrained.norm()) << "seed " << seed;
    EXPECT_NEAR(residual, (a * fit - b).norm(), 1e-10 * b.norm());
    const VecX x = solve_bounded_least_squares(DenseOperator(a), b, VecX::Zero(6));
    EXPECT_LT((x - fit).norm(), 1e-7 * fit.norm()) << "seed " << seed;
  }
}

// tests/data/identify/nnls_scipy.txt: A (40 x 30, sparse-ish, columns over 4 decades), b and scipy.optimize.nnls's
// x, written by scripts/make_nnls_fixture.py with Debian's python3-scipy.
TEST(BoundedLeastSquares, EqualsScipyNnls) {
  std::ifstream in(std::string(HOOKE_TEST_DATA) + "/identify/nnls_scipy.txt");
  ASSERT_TRUE(in.good());
  int rows = 0, cols = 0;
  in >> rows >> cols;
  MatX a(rows, cols);
  VecX b(rows), expected(cols);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) in >> a(r, c);
  for (int r = 0; r < rows; ++r) in >> b(r);
  for (int c = 0; c < cols; ++c) in >> expected(c);
  ASSERT_TRUE(in.good());
  identify::BoundedLeastSquaresReport report;
  const VecX x = solve_bounded_least_squares(DenseOperator(a), b, VecX::Zero(cols), {}, {}, &report);
  EXPECT_TRUE(report.converged);
  int zeros = 0;
  for (int j = 0; j < cols; ++j) {
    EXPECT_NEAR(x(j), expected(j), 1e-8 * std::max(1.0, expected.cwiseAbs().maxCoeff())) << "x" << j;
    zeros += expected(j) == 0.0;
  }
  EXPECT_GT(zeros, 3) << "the fixture should have active bounds";
  EXPECT_EQ(report.at_bound, zeros);
}

TEST(BoundedLeastSquares, MeetsKktOnLargerProblemsWithFreeAndBoundedVariables) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const MatX a = random_matrix(300, 120, seed);
    const VecX b = random_vector(300, 50 + seed);
    VecX lower = VecX::Zero(120);
    for (int j = 0; j < 120; j += 3) lower(j) = -std::numeric_limits<double>::infinity();  // free variables
    for (int j = 1; j < 120; j += 7) lower(j) = -0.5;                                      // other bounds
    identify::BoundedLeastSquaresReport report;
    const VecX x = solve_bounded_least_squares(DenseOperator(a), b, lower, {}, {}, &report);
    EXPECT_TRUE(report.converged) << "seed " << seed << ": " << report.iterations << " iterations, "
                                  << report.cg_iterations << " cg, projected gradient " << report.projected_gradient;
    EXPECT_GT(report.at_bound, 0);
    expect_kkt(a, b, lower, x, 1e-6);
  }
}

TEST(BoundedLeastSquares, UnboundedProblemEqualsNormalEquations) {
  const MatX a = random_matrix(50, 20, 9);
  const VecX b = random_vector(50, 10);
  const VecX lower = VecX::Constant(20, -std::numeric_limits<double>::infinity());
  const VecX x = solve_bounded_least_squares(DenseOperator(a), b, lower);
  const VecX exact = a.colPivHouseholderQr().solve(b);
  for (int j = 0; j < 20; ++j) EXPECT_NEAR(x(j), exact(j), 1e-7 * std::abs(exact(j)) + 1e-12) << j;
}

TEST(BoundedLeastSquares, ZeroColumnIsReportedAndKeepsItsStartOrBound) {
  MatX a = random_matrix(10, 4, 3);
  a.col(2).setZero();
  identify::BoundedLeastSquaresReport report;
  const VecX x = solve_bounded_least_squares(DenseOperator(a), random_vector(10, 4), VecX::Zero(4), {}, {}, &report);
  EXPECT_EQ(report.unseen, 1);
  EXPECT_EQ(x(2), 0.0);
  // With a start, a variable no data sees keeps its start value (at least its bound), and the others still fit.
  const VecX start = VecX::Constant(4, 2.5);
  const VecX y = solve_bounded_least_squares(DenseOperator(a), random_vector(10, 4), VecX::Zero(4), start);
  EXPECT_EQ(y(2), 2.5);
  for (int j : {0, 1, 3}) EXPECT_NEAR(y(j), x(j), 1e-7 * (std::abs(x(j)) + 1.0)) << j;
  VecX low_start = start;
  low_start(2) = -1.0;
  EXPECT_EQ(solve_bounded_least_squares(DenseOperator(a), random_vector(10, 4), VecX::Zero(4), low_start)(2), 0.0);
}

TEST(BoundedLeastSquares, RejectsMismatchedSizesAndNonFiniteData) {
  const DenseOperator a(MatX::Identity(3, 3));
  EXPECT_THROW(solve_bounded_least_squares(a, VecX::Ones(2), VecX::Zero(3)), InvalidArgument);
  VecX b = VecX::Ones(3);
  b(1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(solve_bounded_least_squares(a, b, VecX::Zero(3)), InvalidArgument);
}
