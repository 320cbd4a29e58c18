#pragma once
// Allocation-free sparse kernels shared by the Newton core and the integrators.
#include <hooke/core/types.hpp>
#include <vector>

namespace hooke::solve::detail {

// out = A z for a symmetric matrix stored whole in compressed columns (both triangles): each entry of out is one
// gathered dot product. Threaded from kParallelRows rows on; allocates nothing.
void multiply(const SparseMatrix& a, const VecX& z, VecX& out);

// out += A z for A acting on r interleaved components per row (a per-node matrix on flat node-major vectors).
void add_product(const SparseMatrix& a, const VecX& z, int r, VecX& out);

// Replaces the rows and columns of fixed unknowns by those of the identity; unknown u is fixed when
// fixed[stride * u] (stride = components per unknown of the fixed-DOF flags).
void constrain(SparseMatrix& a, const std::vector<char>& fixed, int stride);

}  // namespace hooke::solve::detail
