// The Newton core against independent answers: a quadratic's minimiser from a dense solve (one iteration, both
// linear solvers), a nonconvex chain started where its Hessian is indefinite (the minimiser checked by its
// gradient and by positive curvature), a force field without a potential (GMRES refinement reaches the dense
// solution of the nonsymmetric system), and the options the core refuses.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/solve/detail/sparse_ops.hpp>
#include <hooke/solve/newton.hpp>

namespace hooke::solve {
namespace {

// phi(z) = sum_i c/4 (z_i^2 - 1)^2 + 1/2 z^T A z - b.z with A a chain Laplacian plus a shift, and an optional
// skew part S added to the gradient only (then there is no potential and the matrix is only approximate).
class ChainObjective final : public NewtonObjective {
 public:
  ChainObjective(int n, double quartic, double skew) : m_quartic(quartic), m_fixed(static_cast<size_t>(n), 0) {
    std::vector<Triplet> t, s;
    for (int i = 0; i < n; ++i) {
      t.emplace_back(i, i, 2.5);
      if (i + 1 < n) {
        t.emplace_back(i, i + 1, -1.0);
        t.emplace_back(i + 1, i, -1.0);
        s.emplace_back(i, i + 1, skew);
        s.emplace_back(i + 1, i, -skew);
      }
      // Every node pair a structural entry: the matrix pattern covers everything the Hessian can hold.
      for (int j = 0; j < n; ++j)
        if (std::abs(i - j) > 1) t.emplace_back(i, j, 0.0);
    }
    m_a.resize(n, n);
    m_a.setFromTriplets(t.begin(), t.end());
    m_skew.resize(n, n);
    m_skew.setFromTriplets(s.begin(), s.end());
    m_matrix = m_a;
    m_b = VecX::LinSpaced(n, 0.5, 1.5);
    m_fixed[0] = 1;  // DOF 0 held at its start value
    for (int i = 0; i < n; ++i)
      for (SparseMatrix::InnerIterator it(m_matrix, i); it; ++it)
        if (it.row() == i) m_diagonal.push_back(static_cast<int>(&it.valueRef() - m_matrix.valuePtr()));
  }
  bool conservative() const override { return m_skew.nonZeros() == 0 || m_skew.norm() == 0.0; }
  bool exact_hessian() const override { return conservative(); }
  const std::vector<char>& fixed() const override { return m_fixed; }
  int dim() const override { return 1; }
  double size() const override { return 1.0; }
  double value(const VecX& z) override {
    return m_quartic / 4.0 * (z.array().square() - 1.0).square().sum() + 0.5 * z.dot(m_a * z) - m_b.dot(z);
  }
  void gradient(const VecX& z, VecX& out) override {
    out = m_quartic * (z.array().cube() - z.array()).matrix() + m_a * z + m_skew * z - m_b;
    out(0) = 0.0;
    m_scale = m_b.norm();
  }
  double force_scale() const override { return m_scale; }
  SparseMatrix& newton_matrix(const VecX& z, bool project) override {
    m_matrix = m_a;
    for (Eigen::Index i = 0; i < z.size(); ++i) {
      const double c = m_quartic * (3.0 * z(i) * z(i) - 1.0);
      m_matrix.valuePtr()[m_diagonal[static_cast<size_t>(i)]] += project ? std::max(c, 0.0) : c;
    }
    detail::constrain(m_matrix, m_fixed, 1);
    return m_matrix;
  }
  const std::vector<int>& diagonal() const override { return m_diagonal; }

  // Dense gradient Jacobian on the free DOFs (DOF 0 held).
  Eigen::MatrixXd free_jacobian(const VecX& z) const {
    Eigen::MatrixXd j = Eigen::MatrixXd(m_a) + Eigen::MatrixXd(m_skew);
    for (Eigen::Index i = 0; i < z.size(); ++i) j(i, i) += m_quartic * (3.0 * z(i) * z(i) - 1.0);
    return j.bottomRightCorner(z.size() - 1, z.size() - 1);
  }
  const SparseMatrix& a() const { return m_a; }
  const SparseMatrix& skew() const { return m_skew; }
  const VecX& b() const { return m_b; }

 private:
  double m_quartic, m_scale = 1.0;
  SparseMatrix m_a, m_skew, m_matrix;
  VecX m_b;
  std::vector<char> m_fixed;
  std::vector<int> m_diagonal;
};

// The free part of the solution of (A + S) z = b with z_0 = start_0, densely.
VecX dense_linear_solution(const ChainObjective& f, const VecX& start) {
  const Eigen::Index n = start.size();
  const Eigen::MatrixXd k = Eigen::MatrixXd(f.a()) + Eigen::MatrixXd(f.skew());
  const VecX rhs = f.b().tail(n - 1) - k.col(0).tail(n - 1) * start(0);
  VecX z = start;
  z.tail(n - 1) = k.bottomRightCorner(n - 1, n - 1).partialPivLu().solve(rhs);
  return z;
}

class NewtonOnAQuadratic : public ::testing::TestWithParam<NewtonLinearSolver> {};

TEST_P(NewtonOnAQuadratic, FindsTheDenseSolutionInOneIteration) {
  ChainObjective f(12, 0.0, 0.0);
  VecX z = VecX::Constant(12, 0.3);
  NewtonOptions o;
  o.linear_solver = GetParam();
  o.cg_tolerance = 1e-12;
  NewtonSolver newton(o);
  const NewtonReport r = newton.solve(f, z);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.iterations, GetParam() == NewtonLinearSolver::kCholesky ? 1 : 3);
  EXPECT_EQ(z(0), 0.3);  // held
  EXPECT_LT((z - dense_linear_solution(f, VecX::Constant(12, 0.3))).norm(), 1e-9);
  if (GetParam() == NewtonLinearSolver::kConjugateGradient) {
    EXPECT_GT(r.linear_iterations, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(LinearSolvers, NewtonOnAQuadratic,
                         ::testing::Values(NewtonLinearSolver::kCholesky, NewtonLinearSolver::kConjugateGradient));

// Started at z = 0, where the quartic's curvature -c makes the Hessian indefinite: the projected fallback and the
// line search still reach a point of zero gradient with positive curvature (a minimiser, not the saddle at 0).
TEST(NewtonSolver, ReachesAMinimiserFromWhereTheHessianIsIndefinite) {
  for (const NewtonLinearSolver solver : {NewtonLinearSolver::kCholesky, NewtonLinearSolver::kConjugateGradient}) {
    ChainObjective f(10, 8.0, 0.0);
    VecX z = VecX::Zero(10), g(10);
    f.gradient(z, g);
    EXPECT_LT(f.free_jacobian(z).selfadjointView<Eigen::Lower>().eigenvalues().minCoeff(), 0.0);
    NewtonOptions o;
    o.linear_solver = solver;
    o.max_iterations = 100;
    NewtonSolver newton(o);
    const double start_value = f.value(z);
    std::vector<double> history;
    const NewtonReport r = newton.solve(f, z, &history);
    ASSERT_TRUE(r.converged) << newton_linear_solver_name(solver);
    f.gradient(z, g);
    EXPECT_LT(g.norm(), 1e-8);
    EXPECT_LT(f.value(z), start_value);
    EXPECT_GT(f.free_jacobian(z).selfadjointView<Eigen::Lower>().eigenvalues().minCoeff(), 0.0);
    EXPECT_EQ(history.size(), static_cast<size_t>(r.iterations + 1));
  }
}

// No potential (a skew coupling in the forces): with the symmetric part as the Newton matrix, GMRES refinement
// recovers the nonsymmetric system's solution; without it the quasi-Newton iteration still converges, more slowly.
TEST(NewtonSolver, RefinesStepsWhereTheHessianIsApproximate) {
  const VecX start = VecX::Constant(9, 0.2);
  ChainObjective refined_f(9, 0.0, 0.3), plain_f(9, 0.0, 0.3);
  VecX refined = start, plain = start;
  NewtonOptions o;
  o.max_iterations = 200;
  const NewtonReport with = NewtonSolver(o).solve(refined_f, refined);
  o.refine_approximate_steps = false;
  const NewtonReport without = NewtonSolver(o).solve(plain_f, plain);
  ASSERT_TRUE(with.converged);
  ASSERT_TRUE(without.converged);
  const VecX exact = dense_linear_solution(refined_f, start);
  EXPECT_LT((refined - exact).norm(), 1e-8);
  EXPECT_LT((plain - exact).norm(), 1e-7);
  EXPECT_LE(with.iterations, 2);
  EXPECT_GT(without.iterations, with.iterations);
}

TEST(NewtonSolver, RefusesOptionsItCannotRunWith) {
  NewtonOptions o;
  o.max_iterations = 0;
  EXPECT_THROW(NewtonSolver{o}, InvalidArgument);
  o = NewtonOptions{};
  o.tolerance = std::nan("");
  EXPECT_THROW(NewtonSolver{o}, InvalidArgument);
  o = NewtonOptions{};
  o.cg_tolerance = 1.0;
  EXPECT_THROW(NewtonSolver{o}, InvalidArgument);
  EXPECT_THROW(newton_linear_solver_from_name("lu"), InvalidArgument);
}

}  // namespace
}  // namespace hooke::solve
