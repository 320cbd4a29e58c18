#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <hooke/core/error.hpp>
#include <hooke/solve/sparse_cholesky.hpp>

namespace hooke::solve {

// Below this many unknowns kAuto uses Eigen's simplicial LDL^T: there CHOLMOD's supernodal path hands tiny
// dense blocks to a threaded BLAS whose threads spend their time waking and yielding. Measured on
// `hooke reproduce lloyd2007` (2 cores): CHOLMOD always 72 s wall; threshold 1 000: 66 s; threshold 5 000:
// 115 s (simplicial fill on the 3 000-DOF tet meshes costs more than the threads do).
constexpr Eigen::Index kSmallSystem = 1000;

struct SparseCholesky::Impl {
  CholeskyBackend requested, backend;
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> cholmod;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt;
  Eigen::Index rows = -1, nonzeros = -1;
  bool analyzed = false, ok = false;
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

std::string_view SparseCholesky::backend_name() const {
  return m_impl->backend == CholeskyBackend::kCholmod ? "cholmod" : "eigen-ldlt";
}

}  // namespace hooke::solve
