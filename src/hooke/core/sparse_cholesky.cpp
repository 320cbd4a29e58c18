#include <dlfcn.h>
#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/core/sparse_cholesky.hpp>
#include <type_traits>
#include <vector>

namespace hooke {

// Below this many unknowns kAuto uses Eigen's simplicial LDL^T: there CHOLMOD's supernodal path hands tiny
// dense blocks to a threaded BLAS whose threads spend their time waking and yielding. Measured on
// `hooke reproduce lloyd2007` (2 cores): CHOLMOD always 72 s wall; threshold 1 000: 66 s; threshold 5 000:
// 115 s (simplicial fill on the 3 000-DOF tet meshes costs more than the threads do).
constexpr Eigen::Index kSmallSystem = 1000;

namespace {

// L L^T x = b for CHOLMOD's supernodal factor of P A P^T, R right-hand sides interleaved, with hand-written dense
// kernels: CHOLMOD's own solve goes through BLAS, whose small-matrix dgemm kernel in OpenBLAS 0.3.21 calls malloc
// on every call (caught by tests/solve/test_simulator_allocation.cpp). w: n x R work; t: max rows x R work.
template <int R>
void supernodal_solve(const cholmod_factor& l, double* b, double* w, double* t) {
  const auto n = static_cast<int>(l.n);
  const int* perm = static_cast<const int*>(l.Perm);
  const int* super = static_cast<const int*>(l.super);
  const int* pi = static_cast<const int*>(l.pi);
  const int* px = static_cast<const int*>(l.px);
  const int* rows = static_cast<const int*>(l.s);
  const double* lx = static_cast<const double*>(l.x);
  const auto nsuper = static_cast<int>(l.nsuper);
  for (int k = 0; k < n; ++k)
    for (int r = 0; r < R; ++r) w[R * k + r] = b[R * perm[k] + r];
  for (int s = 0; s < nsuper; ++s) {  // L y = P b
    const int k1 = super[s], nsc = super[s + 1] - k1, nsrow = pi[s + 1] - pi[s];
    const int* srows = rows + pi[s];
    const double* block = lx + px[s];  // nsrow x nsc, column-major; its first nsc rows are k1 .. k1 + nsc - 1
    const int below = nsrow - nsc;
    std::fill(t, t + static_cast<ptrdiff_t>(below) * R, 0.0);
    for (int j = 0; j < nsc; ++j) {  // diagonal block
      const double* column = block + static_cast<ptrdiff_t>(j) * nsrow;
      for (int r = 0; r < R; ++r) w[R * (k1 + j) + r] /= column[j];
      for (int i = j + 1; i < nsc; ++i)
        for (int r = 0; r < R; ++r) w[R * (k1 + i) + r] -= column[i] * w[R * (k1 + j) + r];
    }
    // Rows below: t = L21 y, four columns per sweep so that t is read and written a quarter as often.
    int j = 0;
    for (; j + 4 <= nsc; j += 4) {
      const double* c0 = block + static_cast<ptrdiff_t>(j) * nsrow + nsc;
      const double *c1 = c0 + nsrow, *c2 = c1 + nsrow, *c3 = c2 + nsrow;
      double y[4][R];
      for (int q = 0; q < 4; ++q)
        for (int r = 0; r < R; ++r) y[q][r] = w[R * (k1 + j + q) + r];
      for (int i = 0; i < below; ++i)
        for (int r = 0; r < R; ++r)
          t[R * i + r] += c0[i] * y[0][r] + c1[i] * y[1][r] + c2[i] * y[2][r] + c3[i] * y[3][r];
    }
    for (; j < nsc; ++j) {
      const double* c0 = block + static_cast<ptrdiff_t>(j) * nsrow + nsc;
      for (int i = 0; i < below; ++i)
        for (int r = 0; r < R; ++r) t[R * i + r] += c0[i] * w[R * (k1 + j) + r];
    }
    for (int i = 0; i < below; ++i)
      for (int r = 0; r < R; ++r) w[R * srows[nsc + i] + r] -= t[R * i + r];
  }
  for (int s = nsuper - 1; s >= 0; --s) {  // L^T z = y
    const int k1 = super[s], nsc = super[s + 1] - k1, nsrow = pi[s + 1] - pi[s];
    const int* srows = rows + pi[s];
    const double* block = lx + px[s];
    const int below = nsrow - nsc;
    for (int i = 0; i < below; ++i)
      for (int r = 0; r < R; ++r) t[R * i + r] = w[R * srows[nsc + i] + r];
    // z_j -= L21(:, j)^T t for every column, four columns per sweep over t.
    int j = 0;
    for (; j + 4 <= nsc; j += 4) {
      const double* c0 = block + static_cast<ptrdiff_t>(j) * nsrow + nsc;
      const double *c1 = c0 + nsrow, *c2 = c1 + nsrow, *c3 = c2 + nsrow;
      double z[4][R] = {};
      for (int i = 0; i < below; ++i)
        for (int r = 0; r < R; ++r) {
          const double ti = t[R * i + r];
          z[0][r] += c0[i] * ti;
          z[1][r] += c1[i] * ti;
          z[2][r] += c2[i] * ti;
          z[3][r] += c3[i] * ti;
        }
      for (int q = 0; q < 4; ++q)
        for (int r = 0; r < R; ++r) w[R * (k1 + j + q) + r] -= z[q][r];
    }
    for (; j < nsc; ++j) {
      const double* c0 = block + static_cast<ptrdiff_t>(j) * nsrow + nsc;
      double z[R] = {};
      for (int i = 0; i < below; ++i)
        for (int r = 0; r < R; ++r) z[r] += c0[i] * t[R * i + r];
      for (int r = 0; r < R; ++r) w[R * (k1 + j) + r] -= z[r];
    }
    for (int jj = nsc - 1; jj >= 0; --jj) {  // diagonal block, backwards
      const double* column = block + static_cast<ptrdiff_t>(jj) * nsrow;
      for (int i = jj + 1; i < nsc; ++i)
        for (int r = 0; r < R; ++r) w[R * (k1 + jj) + r] -= column[i] * w[R * (k1 + i) + r];
      for (int r = 0; r < R; ++r) w[R * (k1 + jj) + r] /= column[jj];
    }
  }
  for (int k = 0; k < n; ++k)
    for (int r = 0; r < R; ++r) b[R * perm[k] + r] = w[R * k + r];
}

// Eigen's CHOLMOD wrapper with access to its factor, for the allocation-free supernodal solve.
class CholmodLLT : public Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> {
 public:
  cholmod_factor* factor() const { return m_cholmodFactor; }
};

// A simplicial LL^T factor of P A P^T in compressed columns, diagonal entry first in each column.
struct SimplicialFactor {
  std::vector<int> start, row, old_of_new;
  std::vector<double> value;
  mutable VecX work;  // n x nrhs, interleaved

  template <int R>
  void solve(double* b) const {
    const auto n = static_cast<int>(old_of_new.size());
    if (work.size() < static_cast<Eigen::Index>(n) * R) work.resize(static_cast<Eigen::Index>(n) * R);
    double* w = work.data();
    for (int k = 0; k < n; ++k)
      for (int r = 0; r < R; ++r) w[R * k + r] = b[R * old_of_new[static_cast<size_t>(k)] + r];
    for (int j = 0; j < n; ++j) {  // L y = P b, by columns
      const int first = start[static_cast<size_t>(j)], last = start[static_cast<size_t>(j) + 1];
      double yj[R];
      for (int r = 0; r < R; ++r) yj[r] = w[R * j + r] /= value[static_cast<size_t>(first)];
      for (int q = first + 1; q < last; ++q) {
        const double l = value[static_cast<size_t>(q)];
        double* wi = w + R * row[static_cast<size_t>(q)];
        for (int r = 0; r < R; ++r) wi[r] -= l * yj[r];
      }
    }
    for (int j = n - 1; j >= 0; --j) {  // L^T z = y, by rows of L^T = columns of L
      const int first = start[static_cast<size_t>(j)], last = start[static_cast<size_t>(j) + 1];
      double zj[R];
      for (int r = 0; r < R; ++r) zj[r] = w[R * j + r];
      for (int q = first + 1; q < last; ++q) {
        const double l = value[static_cast<size_t>(q)];
        const double* wi = w + R * row[static_cast<size_t>(q)];
        for (int r = 0; r < R; ++r) zj[r] -= l * wi[r];
      }
      for (int r = 0; r < R; ++r) w[R * j + r] = zj[r] / value[static_cast<size_t>(first)];
    }
    for (int k = 0; k < n; ++k)
      for (int r = 0; r < R; ++r) b[R * old_of_new[static_cast<size_t>(k)] + r] = w[R * k + r];
  }
};

}  // namespace

struct SparseCholesky::Impl {
  CholeskyBackend requested, backend;
  CholmodLLT cholmod;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt;
  Eigen::Index rows = -1, nonzeros = -1;
  bool analyzed = false, ok = false;
  mutable SimplicialFactor simplicial;
  mutable bool extracted = false;
  mutable VecX supernodal_work, supernodal_rows;  // n x 3 and (largest supernode's rows) x 3

  void cholmod_solve_in_place(double* b, int nrhs) const {
    const cholmod_factor& l = *cholmod.factor();
    if (!l.is_super) throw SolverFailure("SparseCholesky: CHOLMOD returned a simplicial factor");
    if (supernodal_work.size() != 3 * static_cast<Eigen::Index>(l.n)) {
      supernodal_work.resize(3 * static_cast<Eigen::Index>(l.n));
      supernodal_rows.resize(3 * static_cast<Eigen::Index>(l.maxesize) + 3);
    }
    double* w = supernodal_work.data();
    double* t = supernodal_rows.data();
    if (nrhs == 1) supernodal_solve<1>(l, b, w, t);
    if (nrhs == 2) supernodal_solve<2>(l, b, w, t);
    if (nrhs == 3) supernodal_solve<3>(l, b, w, t);
  }

  // Copies Eigen's current factor into `simplicial` (LL^T of P A P^T). @pre backend == kEigen
  void extract() const {
    SimplicialFactor& f = simplicial;
    // Eigen keeps L unit lower (diagonal not stored) and D; LL^T form: columns of L scaled by sqrt(D).
    const auto& lower = ldlt.matrixL().nestedExpression();
    const VecX& d = ldlt.vectorD();
    const auto n = static_cast<size_t>(lower.cols());
    f.start.assign(1, 0);
    f.row.clear();
    f.value.clear();
    for (Eigen::Index j = 0; j < lower.cols(); ++j) {
      const double root = std::sqrt(d(j));
      f.row.push_back(static_cast<int>(j));
      f.value.push_back(root);
      for (std::remove_cvref_t<decltype(lower)>::InnerIterator it(lower, j); it; ++it)
        if (it.row() > j) {
          f.row.push_back(static_cast<int>(it.row()));
          f.value.push_back(it.value() * root);
        }
      f.start.push_back(static_cast<int>(f.row.size()));
    }
    f.old_of_new.resize(n);
    const auto& p = ldlt.permutationP().indices();  // Eigen factors P A P^T with (P b)(p(i)) = b(i)
    if (p.size() == 0)
      for (size_t i = 0; i < n; ++i) f.old_of_new[i] = static_cast<int>(i);
    else
      for (Eigen::Index i = 0; i < p.size(); ++i) f.old_of_new[static_cast<size_t>(p(i))] = static_cast<int>(i);
    extracted = true;
  }
};

SparseCholesky::SparseCholesky(CholeskyBackend backend) : m_impl(std::make_unique<Impl>()) {
  m_impl->requested = backend;
  m_impl->backend = backend == CholeskyBackend::kAuto ? CholeskyBackend::kCholmod : backend;
  // CHOLMOD reports a non-positive-definite matrix through its status; keep it from printing.
  m_impl->cholmod.cholmod().print = 0;
}

SparseCholesky::~SparseCholesky() = default;
SparseCholesky::SparseCholesky(SparseCholesky&&) noexcept = default;
SparseCholesky& SparseCholesky::operator=(SparseCholesky&&) noexcept = default;

bool SparseCholesky::factorize(const SparseMatrix& a) {
  Impl& s = *m_impl;
  const bool same_pattern = s.analyzed && a.rows() == s.rows && a.nonZeros() == s.nonzeros;
  if (!same_pattern && s.requested == CholeskyBackend::kAuto)
    s.backend = a.rows() < kSmallSystem ? CholeskyBackend::kEigen : CholeskyBackend::kCholmod;
  if (s.backend == CholeskyBackend::kCholmod) {
    if (!same_pattern) s.cholmod.analyzePattern(a);
    s.cholmod.factorize(a);
    s.ok = s.cholmod.info() == Eigen::Success;
  } else {
    if (!same_pattern) s.ldlt.analyzePattern(a);
    s.ldlt.factorize(a);
    // LDL^T succeeds on indefinite matrices; positive definiteness needs every pivot positive.
    s.ok = s.ldlt.info() == Eigen::Success && (s.ldlt.vectorD().array() > 0.0).all();
  }
  s.extracted = false;
  s.rows = a.rows();
  s.nonzeros = a.nonZeros();
  s.analyzed = true;
  return s.ok;
}

VecX SparseCholesky::solve(const VecX& b) const {
  if (!m_impl->ok) throw SolverFailure("SparseCholesky::solve called without a successful factorisation");
  if (m_impl->backend == CholeskyBackend::kCholmod) return m_impl->cholmod.solve(b);
  return m_impl->ldlt.solve(b);
}

void SparseCholesky::solve_in_place(double* b, int nrhs) const {
  if (!m_impl->ok) throw SolverFailure("SparseCholesky::solve_in_place called without a successful factorisation");
  if (nrhs < 1 || nrhs > 3) throw InvalidArgument("SparseCholesky::solve_in_place: 1, 2 or 3 right-hand sides");
  if (m_impl->backend == CholeskyBackend::kCholmod) {
    m_impl->cholmod_solve_in_place(b, nrhs);
    return;
  }
  if (!m_impl->extracted) m_impl->extract();
  switch (nrhs) {
    case 1: m_impl->simplicial.solve<1>(b); break;
    case 2: m_impl->simplicial.solve<2>(b); break;
    case 3: m_impl->simplicial.solve<3>(b); break;
    default: break;
  }
}

std::string_view SparseCholesky::backend_name() const {
  return m_impl->backend == CholeskyBackend::kCholmod ? "cholmod" : "eigen-ldlt";
}

}  // namespace hooke
