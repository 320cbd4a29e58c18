#include <hooke/solve/detail/sparse_ops.hpp>

namespace hooke::solve::detail {
namespace {

// Matrix-vector products with at least this many rows run on all threads (measured on two: 34 263 rows 1.6x faster; 3
// 267 rows no faster, the barrier costs what the split saves).
constexpr int kParallelRows = 10000;

}  // namespace

// By symmetry column c holds row c. A plain loop below the threshold: an OpenMP region with if(false) still
// allocates in libgomp, and the time steps must not.
void multiply(const SparseMatrix& a, const VecX& z, VecX& out) {
  const int* start = a.outerIndexPtr();
  const int* rows = a.innerIndexPtr();
  const double* values = a.valuePtr();
  const double* in = z.data();
  double* result = out.data();
  const int n = static_cast<int>(a.outerSize());
  auto row = [&](int c) {
    double sum = 0.0;
    for (int q = start[c]; q < start[c + 1]; ++q) sum += values[q] * in[rows[q]];
    result[c] = sum;
  };
  if (n >= kParallelRows) {
#pragma omp parallel for schedule(static)
    for (int c = 0; c < n; ++c) row(c);
  } else {
    for (int c = 0; c < n; ++c) row(c);
  }
}

void add_product(const SparseMatrix& a, const VecX& z, int r, VecX& out) {
  for (int c = 0; c < a.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(a, c); it; ++it)
      for (int k = 0; k < r; ++k) out(r * it.row() + k) += it.value() * z(r * c + k);
}

void constrain(SparseMatrix& a, const std::vector<char>& fixed, int stride) {
  for (int c = 0; c < a.outerSize(); ++c) {
    const bool column_fixed = fixed[static_cast<size_t>(stride * c)];
    for (SparseMatrix::InnerIterator it(a, c); it; ++it)
      if (column_fixed || fixed[static_cast<size_t>(stride * it.row())]) it.valueRef() = it.row() == c ? 1.0 : 0.0;
  }
}

}  // namespace hooke::solve::detail
