#include <gtest/gtest.h>
#include <omp.h>

#include <support/matrices.hpp>

#include <algorithm>
#include <cmath>
#include <hooke/core/sparse_cholesky.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/topology.hpp>
#include <random>

namespace hooke {
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

// A weighted graph Laplacian of a 7 x 7 x 7 tet box plus a shift: SPD, with a 3D mesh's factor fill.
SparseMatrix mesh_laplacian() {
  const mesh::Mesh m = mesh::tet_box(0.01, 0.01, 0.01, 7, 7, 7);
  std::vector<Triplet> t;
  for (const auto& [i, j] : mesh::unique_edges(m)) {
    const double k = 1.0 + 0.1 * ((i + j) % 7);
    t.insert(t.end(), {{i, i, k}, {j, j, k}, {i, j, -k}, {j, i, -k}});
  }
  for (int i = 0; i < m.node_count(); ++i) t.emplace_back(i, i, 0.05);
  SparseMatrix a(m.node_count(), m.node_count());
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

// A second factorisation of the same pattern takes CHOLMOD's ordering from the first, and its factor is the same
// bits; the same size and nonzero count with other indices (the nodes renumbered) is a different pattern.
TEST(SparseCholesky, SharesTheOrderingOfAPatternAndKeepsTheFactor) {
  const mesh::Mesh m = mesh::tet_box(0.01, 0.01, 0.01, 5, 6, 7);
  auto laplacian = [&m](const std::vector<int>& label) {
    std::vector<Triplet> t;
    for (const auto& [i, j] : mesh::unique_edges(m)) {
      const int a = label[static_cast<size_t>(i)], b = label[static_cast<size_t>(j)];
      t.insert(t.end(), {{a, a, 1.0}, {b, b, 1.0}, {a, b, -1.0}, {b, a, -1.0}});
    }
    for (int i = 0; i < m.node_count(); ++i) t.emplace_back(i, i, 0.1);
    SparseMatrix a(m.node_count(), m.node_count());
    a.setFromTriplets(t.begin(), t.end());
    return a;
  };
  std::vector<int> identity(static_cast<size_t>(m.node_count()));
  for (int i = 0; i < m.node_count(); ++i) identity[static_cast<size_t>(i)] = i;
  std::vector<int> shuffled = identity;  // (reversing the numbering maps the box onto itself: the same pattern)
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(11));
  const SparseMatrix a = laplacian(identity), renumbered = laplacian(shuffled);
  ASSERT_EQ(a.nonZeros(), renumbered.nonZeros());
  const VecX b = VecX::LinSpaced(a.rows(), -1.0, 1.0);
  SparseCholesky first(CholeskyBackend::kCholmod), second(CholeskyBackend::kCholmod), other(CholeskyBackend::kCholmod);
  ASSERT_TRUE(first.factorize(a));
  EXPECT_FALSE(first.reused_ordering());
  ASSERT_TRUE(second.factorize(a));
  EXPECT_TRUE(second.reused_ordering());
  const VecX x1 = first.solve(b), x2 = second.solve(b);
  EXPECT_EQ(x1, x2);  // the same permutation and the same factor: identical bits
  EXPECT_LT((a * x2 - b).norm(), 1e-9 * b.norm());
  ASSERT_TRUE(other.factorize(renumbered));
  EXPECT_FALSE(other.reused_ordering());
  EXPECT_LT((renumbered * other.solve(b) - b).norm(), 1e-9 * b.norm());
}

// solve_in_place: 1-3 interleaved right-hand sides, on a 3D mesh Laplacian whose CHOLMOD factor has real
// supernodes (the hand-written supernodal kernels run through blocks of 4 columns and their remainders).
TEST(SparseCholesky, SolveInPlaceMatchesTheResidualForSeveralRightHandSides) {
  const SparseMatrix a = mesh_laplacian();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (CholeskyBackend backend : {CholeskyBackend::kCholmod, CholeskyBackend::kEigen}) {
    SparseCholesky c(backend);
    ASSERT_TRUE(c.factorize(a));
    for (int r = 1; r <= 3; ++r) {
      VecX b(static_cast<Eigen::Index>(r) * a.rows());
      for (Eigen::Index i = 0; i < b.size(); ++i) b(i) = u(rng);
      VecX x = b;
      c.solve_in_place(x.data(), r);
      for (int k = 0; k < r; ++k) {
        const VecX bk =
            Eigen::Map<const VecX, 0, Eigen::InnerStride<>>(b.data() + k, a.rows(), Eigen::InnerStride<>(r));
        const VecX xk =
            Eigen::Map<const VecX, 0, Eigen::InnerStride<>>(x.data() + k, a.rows(), Eigen::InnerStride<>(r));
        EXPECT_LT((a * xk - bk).norm(), 1e-11 * bk.norm()) << c.backend_name() << ", " << r << " right-hand sides";
      }
    }
  }
}

// The single-precision solve (quasi-Newton's initial Hessian): a float copy of the supernodal factor, refreshed at
// every factorisation; about 1e-7 relative error, not double's 1e-15; solve() and solve_exact_in_place() stay in
// double.
TEST(SparseCholesky, SinglePrecisionSolveIsAFloatCopyOfTheFactor) {
  const SparseMatrix a = mesh_laplacian();
  SparseCholesky exact(CholeskyBackend::kCholmod), single(CholeskyBackend::kCholmod);
  single.set_solve_precision(SolvePrecision::kSingle);
  const VecX b = VecX::LinSpaced(a.rows(), -1.0, 2.0);
  for (double scale : {1.0, 3.0}) {  // a second factorisation refreshes the copy
    const SparseMatrix as = a * scale;
    ASSERT_TRUE(exact.factorize(as));
    ASSERT_TRUE(single.factorize(as));
    VecX xd = b, xs = b, x3(3 * a.rows());
    exact.solve_in_place(xd.data(), 1);
    single.solve_in_place(xs.data(), 1);
    const double error = (xs - xd).norm() / xd.norm();
    EXPECT_GT(error, 1e-12) << "the float path did not run";
    EXPECT_LT(error, 1e-5);
    EXPECT_LT((single.solve(b) - xd).norm(), 1e-12 * xd.norm());  // solve() is double
    VecX xe = b;
    single.solve_exact_in_place(xe.data(), 1);
    EXPECT_EQ(xe, xd);  // the same double kernel on the same factor
    for (Eigen::Index i = 0; i < a.rows(); ++i) x3.segment<3>(3 * i).setConstant(b(i));
    single.solve_in_place(x3.data(), 3);
    for (int r = 0; r < 3; ++r)
      EXPECT_EQ(VecX(Eigen::Map<const VecX, 0, Eigen::InnerStride<3>>(x3.data() + r, a.rows())), xs);
  }
  single.set_solve_precision(SolvePrecision::kDouble);  // back to double on the current factor
  VecX xd = b;
  single.solve_in_place(xd.data(), 1);
  EXPECT_LT((SparseMatrix(a * 3.0) * xd - b).norm(), 1e-11 * b.norm());
}

// The bfloat16 solve (quasi-Newton's initial Hessian on large meshes) is the exact inverse of L~ L~^T, L~ the factor
// rounded to 8 significant bits: symmetric and positive definite to float round-off, within ~1e-2 of A^-1, and
// the same to float round-off for each of 3 interleaved right-hand sides.
TEST(SparseCholesky, Bfloat16SolveIsSymmetricPositiveDefiniteAndNearTheExactOne) {
  const SparseMatrix a = mesh_laplacian();
  SparseCholesky exact(CholeskyBackend::kCholmod), brain(CholeskyBackend::kCholmod);
  brain.set_solve_precision(SolvePrecision::kBfloat16);
  ASSERT_TRUE(exact.factorize(a));
  ASSERT_TRUE(brain.factorize(a));
  const VecX u = VecX::LinSpaced(a.rows(), -1.0, 2.0);
  VecX v(a.rows());
  for (Eigen::Index i = 0; i < a.rows(); ++i) v(i) = std::sin(0.7 * static_cast<double>(i)) + 0.3;
  const auto apply = [&](const SparseCholesky& f, const VecX& b) {
    VecX x = b;
    f.solve_in_place(x.data(), 1);
    return x;
  };
  const VecX su = apply(brain, u), sv = apply(brain, v), xu = apply(exact, u);
  const double error = (su - xu).norm() / xu.norm();
  EXPECT_GT(error, 1e-5) << "the bfloat16 path did not run";
  EXPECT_LT(error, 1e-2);
  EXPECT_NEAR(u.dot(sv), v.dot(su), 1e-5 * su.norm() * v.norm());  // symmetric
  EXPECT_GT(u.dot(su), 0.0);                                       // positive
  EXPECT_GT(v.dot(sv), 0.0);
  VecX x3(3 * a.rows());
  for (Eigen::Index i = 0; i < a.rows(); ++i) x3.segment<3>(3 * i) << u(i), v(i), u(i);
  brain.solve_in_place(x3.data(), 3);
  for (int r = 0; r < 3; ++r) {  // one right-hand side has its own kernel (AVX2 and FMA): the same to float round-off
    const VecX& alone = r == 1 ? sv : su;
    EXPECT_LT((VecX(Eigen::Map<const VecX, 0, Eigen::InnerStride<3>>(x3.data() + r, a.rows())) - alone).norm(),
              1e-6 * alone.norm());
  }
  brain.set_solve_precision(SolvePrecision::kSingle);  // switching copies the current factor
  EXPECT_LT((apply(brain, u) - xu).norm(), 1e-5 * xu.norm());
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

// A factor of more than 4 M entries whose tree splits evenly solves on two threads: the same answer as CHOLMOD's own
// solve (double), within float round-off of it (float copy) or bfloat16's 1e-2 (and symmetric), the same bits on
// one thread or two, and each of 3 interleaved right-hand sides as alone (bfloat16: to float round-off, one
// right-hand side having its own kernel).
TEST(SparseCholesky, LargeFactorsSolveOnTwoThreads) {
  const int gx = 16, gy = 16, gz = 160;  // a bar's grid, 7-point Laplacian, shifted: its separators are small
  auto index = [&](int x, int y, int z) { return (z * gy + y) * gx + x; };
  std::vector<Triplet> t;
  for (int z = 0; z < gz; ++z)
    for (int y = 0; y < gy; ++y)
      for (int x = 0; x < gx; ++x) {
        const int i = index(x, y, z);
        t.emplace_back(i, i, 6.01);
        for (const int j : {x + 1 < gx ? index(x + 1, y, z) : -1, y + 1 < gy ? index(x, y + 1, z) : -1,
                            z + 1 < gz ? index(x, y, z + 1) : -1})
          if (j >= 0) t.insert(t.end(), {{i, j, -1.0}, {j, i, -1.0}});
      }
  SparseMatrix a(gx * gy * gz, gx * gy * gz);
  a.setFromTriplets(t.begin(), t.end());
  SparseCholesky c(CholeskyBackend::kCholmod);
  ASSERT_TRUE(c.factorize(a));
  ASSERT_TRUE(c.parallel_solve());
  const VecX b = VecX::LinSpaced(a.rows(), -1.0, 2.0);
  const VecX reference = c.solve(b);
  const int threads = omp_get_max_threads();
  for (SolvePrecision p : {SolvePrecision::kDouble, SolvePrecision::kSingle, SolvePrecision::kBfloat16}) {
    c.set_solve_precision(p);
    std::vector<VecX> x;
    for (int n : {1, 2}) {
      omp_set_num_threads(n);
      x.push_back(b);
      c.solve_in_place(x.back().data(), 1);
    }
    omp_set_num_threads(threads);
    EXPECT_EQ(x[0], x[1]);
    const double tolerance = p == SolvePrecision::kDouble ? 1e-12 : p == SolvePrecision::kSingle ? 1e-5 : 1e-2;
    EXPECT_LT((x[0] - reference).norm(), tolerance * reference.norm());
    if (p == SolvePrecision::kBfloat16) {  // still the inverse of a symmetric matrix: the spill is added back whole
      VecX v(a.rows());
      for (Eigen::Index i = 0; i < a.rows(); ++i) v(i) = std::sin(0.7 * static_cast<double>(i)) + 0.3;
      VecX sv = v;
      c.solve_in_place(sv.data(), 1);
      EXPECT_NEAR(b.dot(sv), v.dot(x[0]), 1e-5 * sv.norm() * b.norm());
    }
    VecX x3(3 * a.rows());
    for (Eigen::Index i = 0; i < a.rows(); ++i) x3.segment<3>(3 * i).setConstant(b(i));
    c.solve_in_place(x3.data(), 3);
    for (int r = 0; r < 3; ++r) {
      const VecX xr = Eigen::Map<const VecX, 0, Eigen::InnerStride<3>>(x3.data() + r, a.rows());
      if (p == SolvePrecision::kBfloat16)  // one right-hand side has its own kernel (AVX2 and FMA)
        EXPECT_LT((xr - x[0]).norm(), 1e-6 * x[0].norm());
      else
        EXPECT_EQ(xr, x[0]);
    }
  }
}

}  // namespace
}  // namespace hooke
