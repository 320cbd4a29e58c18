#include <hooke/solve/detail/sparse_ops.hpp>

namespace hooke::solve::detail {
namespace {

// Matrix-vector products with at least this many rows run on all threads (measured on two: 34 263 rows 1.6x faster; 3
// 267 rows no faster, the barrier costs what the split saves).
constexpr int kParallelRows = 10000;

// Runs f(0 .. count - 1), on all threads when `rows` reaches kParallelRows. A plain loop below it: an OpenMP region
// with if(false) still allocates in libgomp, and the time steps must not.
template <class F>
void for_each_index(int count, int rows, const F& f) {
  if (rows >= kParallelRows) {
#pragma omp parallel for schedule(static)
    for (int i = 0; i < count; ++i) f(i);
  } else {
    for (int i = 0; i < count; ++i) f(i);
  }
}

}  // namespace

// By symmetry column c holds row c.
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
  for_each_index(n, n, row);
}

bool node_blocked(const SparseMatrix& a, int d) {
  const int* start = a.outerIndexPtr();
  const int* rows = a.innerIndexPtr();
  const auto n = static_cast<int>(a.outerSize());
  if (d < 1 || n % d != 0 || !a.isCompressed()) return false;
  for (int c0 = 0; c0 < n; c0 += d) {
    const int len = start[c0 + 1] - start[c0];
    if (len % d != 0) return false;
    for (int k = 0; k < d; ++k) {
      const int s = start[c0 + k];
      if (start[c0 + k + 1] - s != len) return false;
      for (int q = 0; q < len; ++q)
        if (rows[s + q] != rows[start[c0] + q] ||
            (q % d == 0 ? rows[s + q] % d != 0 : rows[s + q] != rows[s + q - 1] + 1))
          return false;
    }
  }
  return true;
}

void multiply_blocked3(const SparseMatrix& a, const VecX& z, VecX& out) {
  const int* start = a.outerIndexPtr();
  const int* rows = a.innerIndexPtr();
  const double* values = a.valuePtr();
  const double* in = z.data();
  double* result = out.data();
  const int nodes = static_cast<int>(a.outerSize()) / 3;
  auto node = [&](int i) {
    const int s0 = start[3 * i], s1 = start[3 * i + 1], s2 = start[3 * i + 2], len = s1 - s0;
    double sum0 = 0.0, sum1 = 0.0, sum2 = 0.0;
    for (int q = 0; q < len; q += 3) {
      const double* zr = in + rows[s0 + q];
      const double z0 = zr[0], z1 = zr[1], z2 = zr[2];
      sum0 += values[s0 + q] * z0 + values[s0 + q + 1] * z1 + values[s0 + q + 2] * z2;
      sum1 += values[s1 + q] * z0 + values[s1 + q + 1] * z1 + values[s1 + q + 2] * z2;
      sum2 += values[s2 + q] * z0 + values[s2 + q + 1] * z1 + values[s2 + q + 2] * z2;
    }
    result[3 * i] = sum0;
    result[3 * i + 1] = sum1;
    result[3 * i + 2] = sum2;
  };
  for_each_index(nodes, 3 * nodes, node);
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

void Constraint::apply(SparseMatrix& a, const std::vector<char>& fixed, int stride) {
  if (a.rows() != m_rows || a.nonZeros() != m_nonzeros || stride != m_stride || fixed != m_fixed) {
    m_zero.clear();
    m_one.clear();
    for (int c = 0; c < a.outerSize(); ++c) {
      const bool column_fixed = fixed[static_cast<size_t>(stride * c)];
      for (SparseMatrix::InnerIterator it(a, c); it; ++it)
        if (column_fixed || fixed[static_cast<size_t>(stride * it.row())])
          (it.row() == c ? m_one : m_zero).push_back(static_cast<int>(&it.valueRef() - a.valuePtr()));
    }
    m_rows = a.rows();
    m_nonzeros = a.nonZeros();
    m_stride = stride;
    m_fixed = fixed;
  }
  double* values = a.valuePtr();
  for (int q : m_zero) values[q] = 0.0;
  for (int q : m_one) values[q] = 1.0;
}

}  // namespace hooke::solve::detail
