// The sparse kernels under the Newton core against dense Eigen: the node-blocked product equals the dense product
// on a random symmetric matrix of 3 x 3 node blocks (and the block check refuses matrices that are not), and the
// cached constraint writes exactly what constrain() writes, also after the fixed flags change.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <hooke/solve/detail/sparse_ops.hpp>
#include <random>
#include <vector>

namespace hooke::solve::detail {
namespace {

// A symmetric matrix of whole 3 x 3 blocks on a random node graph (plus every diagonal block), both triangles stored.
SparseMatrix random_block_matrix(int nodes, int edges, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> node(0, nodes - 1);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> t;
  auto block = [&](int i, int j) {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const double v = value(rng);
        t.emplace_back(3 * i + a, 3 * j + b, v);
        if (i != j) t.emplace_back(3 * j + b, 3 * i + a, v);
      }
  };
  for (int i = 0; i < nodes; ++i) block(i, i);
  for (int e = 0; e < edges; ++e) {
    const int i = node(rng), j = node(rng);
    if (i != j) block(i, j);
  }
  SparseMatrix a(3 * nodes, 3 * nodes);
  a.setFromTriplets(t.begin(), t.end());
  const SparseMatrix symmetric = 0.5 * (SparseMatrix(a.transpose()) + a);
  SparseMatrix out = symmetric;
  out.makeCompressed();
  return out;
}

TEST(SparseOps, BlockedProductEqualsTheDenseProduct) {
  for (int nodes : {1, 7, 400, 4000}) {  // 4 000 nodes: 12 000 rows, the threaded path
    const SparseMatrix a = random_block_matrix(nodes, 4 * nodes, 17u + static_cast<unsigned>(nodes));
    ASSERT_TRUE(node_blocked(a, 3));
    const VecX z = VecX::Random(a.rows());
    VecX blocked(a.rows()), scalar(a.rows());
    multiply_blocked3(a, z, blocked);
    multiply(a, z, scalar);
    const VecX dense = Eigen::MatrixXd(a) * z;
    EXPECT_LE((blocked - dense).norm(), 1e-12 * dense.norm()) << nodes << " nodes";
    EXPECT_LE((scalar - dense).norm(), 1e-12 * dense.norm()) << nodes << " nodes";
  }
}

TEST(SparseOps, BlockCheckRefusesPartialBlocks) {
  SparseMatrix a = random_block_matrix(20, 60, 3u);
  EXPECT_FALSE(node_blocked(a, 2));  // 60 rows in blocks of 3 are not whole 2 x 2 blocks
  // One entry fewer in one column: the node's columns no longer hold the same rows.
  std::vector<Eigen::Triplet<double>> t;
  for (int c = 0; c < a.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(a, c); it; ++it)
      if (!(it.row() == 4 && c == 5)) t.emplace_back(static_cast<int>(it.row()), c, it.value());
  SparseMatrix b(a.rows(), a.cols());
  b.setFromTriplets(t.begin(), t.end());
  b.makeCompressed();
  EXPECT_FALSE(node_blocked(b, 3));
  // A scalar diagonal matrix is not made of 3 x 3 blocks either.
  SparseMatrix d(9, 9);
  d.setIdentity();
  d.makeCompressed();
  EXPECT_FALSE(node_blocked(d, 3));
  EXPECT_TRUE(node_blocked(d, 1));
}

TEST(SparseOps, CachedConstraintWritesWhatConstrainWrites) {
  const SparseMatrix a = random_block_matrix(50, 150, 5u);
  std::vector<char> fixed(static_cast<size_t>(a.rows()), 0);
  for (int i : {0, 1, 2, 31, 77, 149}) fixed[static_cast<size_t>(i)] = 1;
  Constraint cached;
  for (int round = 0; round < 3; ++round) {
    if (round == 2) fixed[40] = 1;  // the flags change: the cache must follow
    SparseMatrix expected = a, got = a;
    constrain(expected, fixed, 1);
    cached.apply(got, fixed, 1);
    EXPECT_EQ(Eigen::MatrixXd(got), Eigen::MatrixXd(expected)) << "round " << round;
  }
}

}  // namespace
}  // namespace hooke::solve::detail
