#pragma once
// Allocation-free sparse kernels shared by the Newton core and the integrators.
#include <hooke/core/types.hpp>
#include <vector>

namespace hooke::solve::detail {

// out = A z for a symmetric matrix stored whole in compressed columns (both triangles): each entry of out is one
// gathered dot product. Threaded from kParallelRows rows on; allocates nothing.
void multiply(const SparseMatrix& a, const VecX& z, VecX& out);

// True when `a` (both triangles, compressed columns) is made of whole d x d node blocks: the d columns of each node
// hold the same rows, in runs of d consecutive rows starting at a multiple of d. O(nonzeros).
bool node_blocked(const SparseMatrix& a, int d);

// out = A z for a symmetric matrix of whole 3 x 3 node blocks (node_blocked(a, 3)): one row index and one gather of
// three entries of z per block, against one per entry in multiply(). Threaded like multiply(); allocates nothing.
void multiply_blocked3(const SparseMatrix& a, const VecX& z, VecX& out);

// out += A z for A acting on r interleaved components per row (a per-node matrix on flat node-major vectors).
void add_product(const SparseMatrix& a, const VecX& z, int r, VecX& out);

// Replaces the rows and columns of fixed unknowns by those of the identity; unknown u is fixed when
// fixed[stride * u] (stride = components per unknown of the fixed-DOF flags).
void constrain(SparseMatrix& a, const std::vector<char>& fixed, int stride);

// constrain() for repeated use on one pattern: the entries it overwrites are found once (O(nonzeros)) and then
// written directly, until the pattern or the fixed flags change.
class Constraint {
 public:
  void apply(SparseMatrix& a, const std::vector<char>& fixed, int stride);

 private:
  std::vector<char> m_fixed;
  Eigen::Index m_rows = -1, m_nonzeros = -1;
  int m_stride = 0;
  std::vector<int> m_zero, m_one;  // offsets into the values
};

}  // namespace hooke::solve::detail
