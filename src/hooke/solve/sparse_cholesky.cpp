#include <dlfcn.h>
#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>

#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/solve/sparse_cholesky.hpp>
#include <type_traits>
#include <vector>

namespace hooke::solve {

// Below this many unknowns kAuto uses Eigen's simplicial LDL^T: there CHOLMOD's supernodal path hands tiny
// dense blocks to a threaded BLAS whose threads spend their time waking and yielding. Measured on
// `hooke reproduce lloyd2007` (2 cores): CHOLMOD always 72 s wall; threshold 1 000: 66 s; threshold 5 000:
// 115 s (simplicial fill on the 3 000-DOF tet meshes costs more than the threads do).
constexpr Eigen::Index kSmallSystem = 1000;

namespace {

// OpenBLAS's thread count, when OpenBLAS is the BLAS CHOLMOD runs on (looked up at run time: the reference BLAS
// has no such calls). The real-time solves run single-threaded: their dense blocks are small, and BLAS threads
// that wake for each of them compete with the element loops' OpenMP threads for the two cores (measured on the
// 11 025-node local/global step: 47 ms with both, 31 ms with single-threaded BLAS).
struct BlasThreads {
  using Set = void (*)(int);
  using Get = int (*)();
  Set set = reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  Get get = reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
};

const BlasThreads& blas_threads() {
  static const BlasThreads threads;
  return threads;
}

// Runs the enclosing scope with one BLAS thread.
class SingleThreadedBlas {
 public:
  SingleThreadedBlas() : m_previous(blas_threads().get && blas_threads().set ? blas_threads().get() : 0) {
    if (m_previous > 1) blas_threads().set(1);
  }
  ~SingleThreadedBlas() {
    if (m_previous > 1) blas_threads().set(m_previous);
  }
  SingleThreadedBlas(const SingleThreadedBlas&) = delete;
  SingleThreadedBlas& operator=(const SingleThreadedBlas&) = delete;

 private:
  int m_previous;
};

// Eigen's CHOLMOD wrapper with access to its factor, to copy it into simplicial form.
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
  mutable CholmodLLT cholmod;  // mutable: Eigen gives its cholmod_common through a non-const accessor
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt;
  Eigen::Index rows = -1, nonzeros = -1;
  bool analyzed = false, ok = false;
  mutable SimplicialFactor simplicial;
  mutable bool extracted = false;
  // cholmod_solve2 reuses these dense arrays when their sizes match: no allocation per solve.
  mutable cholmod_dense *rhs = nullptr, *solution = nullptr, *work_y = nullptr, *work_e = nullptr;

  ~Impl() {
    for (cholmod_dense** d : {&rhs, &solution, &work_y, &work_e})
      if (*d) cholmod_free_dense(d, &cholmod.cholmod());
  }
  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  // Supernodal solve of CHOLMOD for nrhs interleaved right-hand sides (transposed to and from its columns).
  void cholmod_solve_in_place(double* b, int nrhs) const {
    cholmod_common& c = cholmod.cholmod();
    const auto n = static_cast<size_t>(rows);
    if (!rhs || rhs->ncol != static_cast<size_t>(nrhs)) {
      if (rhs) cholmod_free_dense(&rhs, &c);
      rhs = cholmod_allocate_dense(n, static_cast<size_t>(nrhs), n, CHOLMOD_REAL, &c);
      if (!rhs) throw SolverFailure("CHOLMOD could not allocate a right-hand side (out of memory?)");
    }
    double* column_major = static_cast<double*>(rhs->x);
    for (size_t i = 0; i < n; ++i)
      for (int r = 0; r < nrhs; ++r)
        column_major[static_cast<size_t>(r) * n + i] = b[static_cast<size_t>(nrhs) * i + static_cast<size_t>(r)];
    const SingleThreadedBlas single;
    if (!cholmod_solve2(CHOLMOD_A, cholmod.factor(), rhs, nullptr, &solution, nullptr, &work_y, &work_e, &c))
      throw SolverFailure("CHOLMOD's solve failed");
    const double* x = static_cast<const double*>(solution->x);
    for (size_t i = 0; i < n; ++i)
      for (int r = 0; r < nrhs; ++r)
        b[static_cast<size_t>(nrhs) * i + static_cast<size_t>(r)] = x[static_cast<size_t>(r) * n + i];
  }

  // Copies the current factor into `simplicial` (LL^T, P A P^T).
  void extract() const {
    SimplicialFactor& f = simplicial;
    if (backend == CholeskyBackend::kCholmod) {
      cholmod_common& c = cholmod.cholmod();
      cholmod_factor* l = cholmod_copy_factor(cholmod.factor(), &c);
      if (!l || !cholmod_change_factor(CHOLMOD_REAL, 1, 0, 1, 1, l, &c)) {
        if (l) cholmod_free_factor(&l, &c);
        throw SolverFailure("CHOLMOD could not convert its factor to simplicial form (out of memory?)");
      }
      const auto n = static_cast<size_t>(l->n);
      const int* p = static_cast<const int*>(l->p);
      f.start.assign(p, p + n + 1);
      f.row.assign(static_cast<const int*>(l->i), static_cast<const int*>(l->i) + p[n]);
      f.value.assign(static_cast<const double*>(l->x), static_cast<const double*>(l->x) + p[n]);
      f.old_of_new.assign(static_cast<const int*>(l->Perm), static_cast<const int*>(l->Perm) + n);
      cholmod_free_factor(&l, &c);
    } else {
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
    }
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

Eigen::Index SparseCholesky::factor_nonzeros() const {
  if (!m_impl->ok) return 0;
  if (!m_impl->extracted) m_impl->extract();
  return static_cast<Eigen::Index>(m_impl->simplicial.value.size());
}

std::string_view SparseCholesky::backend_name() const {
  return m_impl->backend == CholeskyBackend::kCholmod ? "cholmod" : "eigen-ldlt";
}

}  // namespace hooke::solve
