#pragma once
/// Sparse symmetric positive-definite factorisation: CHOLMOD supernodal (SuiteSparse) or Eigen's
/// SimplicialLDLT as a fallback. The symbolic analysis is kept and reused while the pattern is unchanged.
#include <hooke/core/types.hpp>
#include <memory>
#include <string_view>

namespace hooke {

enum class CholeskyBackend {
  kAuto,     ///< Eigen below 5 000 unknowns (no threaded-BLAS overhead), CHOLMOD from there on
  kCholmod,  ///< CHOLMOD supernodal LL^T
  kEigen     ///< Eigen::SimplicialLDLT (fine below ~5 000 DOFs)
};

class SparseCholesky {
 public:
  explicit SparseCholesky(CholeskyBackend backend = CholeskyBackend::kAuto);
  ~SparseCholesky();
  SparseCholesky(SparseCholesky&&) noexcept;
  SparseCholesky& operator=(SparseCholesky&&) noexcept;

  /// Factorises the symmetric matrix `a` (both triangles stored, N/m). Reuses the symbolic analysis when
  /// the sparsity pattern matches the previous call.
  /// @return true when `a` is numerically positive definite and the factorisation succeeded
  bool factorize(const SparseMatrix& a);
  /// Solves A x = b with the last successful factorisation. @pre factorize() returned true
  VecX solve(const VecX& b) const;
  /// Solves A X = B in place for `nrhs` (1, 2 or 3) right-hand sides stored interleaved, b[nrhs i + r] (a
  /// row-major n x nrhs array: flat node-major positions when A is a per-node matrix). Single-threaded triangular
  /// solves on CHOLMOD's supernodal factor, or on a copy of Eigen's factor made at the first call after a
  /// factorisation. Allocates nothing after the first call. @pre factorize() returned true
  void solve_in_place(double* b, int nrhs) const;
  /// With `on`, solve_in_place on the CHOLMOD backend uses a single-precision copy of the factor, made at each
  /// factorisation (half the memory traffic of the triangular solves; relative error about 1e-7 x the condition
  /// number's effect on the solve): for preconditioners such as quasi-Newton's initial Hessian, never for a
  /// solution. solve() and the Eigen backend stay in double precision. Default off.
  void set_single_precision_solve(bool on);
  /// "cholmod" or "eigen-ldlt".
  std::string_view backend_name() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace hooke
