#pragma once
// Projection of a small symmetric matrix onto the positive semi-definite cone (negative eigenvalues -> 0).
// One compiled eigen-solver serves every element size (measured: instantiating Eigen's solver for each fixed size in
// each element block took 22 of the 28 s that fem/elastic_block.cpp took to compile, twice that under UBSan).
#include <Eigen/Core>

namespace hooke::detail {

inline constexpr int kMaxPsdSize = 12;  // a tet's 12 x 12 element Hessian is the largest projected

// Replaces the column-major n x n symmetric matrix at m by its projection onto the PSD cone (the nearest PSD matrix
// in the Frobenius norm: negative eigenvalues set to zero). Unchanged when it is already PSD. Needs 1 <= n <= 12.
void project_to_psd(double* m, int n);

// The same for a fixed-size Eigen matrix of at most 12 x 12.
template <typename Matrix>
void project_to_psd(Matrix& m) {
  static_assert(Matrix::RowsAtCompileTime == Matrix::ColsAtCompileTime && Matrix::RowsAtCompileTime > 0 &&
                Matrix::RowsAtCompileTime <= kMaxPsdSize && !Matrix::IsRowMajor);
  project_to_psd(m.data(), static_cast<int>(Matrix::RowsAtCompileTime));
}

}  // namespace hooke::detail
