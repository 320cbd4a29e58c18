#pragma once
// Sparse test matrices with known spectra.
#include <hooke/core/types.hpp>
#include <vector>

namespace hooke::test {

// n x n tridiag(-1, 2 + shift, -1): eigenvalues shift + 2 - 2 cos(k pi / (n + 1)), k = 1..n.
inline SparseMatrix shifted_laplacian(int n, double shift) {
  std::vector<Triplet> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0 + shift);
    if (i + 1 < n) {
      t.emplace_back(i, i + 1, -1.0);
      t.emplace_back(i + 1, i, -1.0);
    }
  }
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

}  // namespace hooke::test
