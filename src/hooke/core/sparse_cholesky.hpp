#pragma once
/// Sparse symmetric positive-definite factorisation: CHOLMOD supernodal (SuiteSparse) or Eigen's
/// SimplicialLDLT as a fallback. The symbolic analysis is kept and reused while the pattern is unchanged, and
/// CHOLMOD's fill-reducing ordering is shared between factorisations of the same pattern.
#include <hooke/core/types.hpp>
#include <memory>
#include <string_view>

namespace hooke {

enum class CholeskyBackend {
  kAuto,     ///< Eigen below 1 000 unknowns (no threaded-BLAS overhead), CHOLMOD from there on
  kCholmod,  ///< CHOLMOD supernodal LL^T
  kEigen     ///< Eigen::SimplicialLDLT (fine below ~5 000 DOFs)
};

/// The factor solve_in_place reads. Below kDouble the solve is the exact inverse (to float round-off) of L~ L~^T
/// with L~ the factor rounded, so still symmetric positive definite, for less memory traffic.
enum class SolvePrecision {
  kDouble,   ///< CHOLMOD's own factor: relative error ~1e-15 x conditioning
  kSingle,   ///< a float copy: half the traffic, ~1e-7
  kBfloat16  ///< a bfloat16 copy (8 significant bits) in float arithmetic: a quarter of the traffic, ~4e-3
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
  /// row-major n x nrhs array: flat node-major positions when A is a per-node matrix). Triangular solves on
  /// CHOLMOD's supernodal factor (on two threads where parallel_solve()), or on a copy of
  /// Eigen's factor made at the first call after a factorisation. Allocates nothing after the first call.
  /// @pre factorize() returned true
  void solve_in_place(double* b, int nrhs) const;
  /// As solve_in_place, always on the double-precision factor whatever set_solve_precision chose: the solution
  /// beside preconditioner solves on the same factor. Allocates nothing after the first call.
  void solve_exact_in_place(double* b, int nrhs) const;
  /// The precision of solve_in_place on the CHOLMOD backend: below kDouble it solves on a reduced-precision copy
  /// of the factor, made at each factorisation (see SolvePrecision): for preconditioners such as quasi-Newton's
  /// initial Hessian or Newton's kept-factor CG, never for a solution. solve(), solve_exact_in_place() and the
  /// Eigen backend stay in double precision.
  void set_solve_precision(SolvePrecision precision);
  /// True when the last symbolic analysis took its fill-reducing ordering from an earlier analysis of the same
  /// pattern in this process (CHOLMOD backend; a few recent patterns are kept) instead of computing it again.
  bool reused_ordering() const;
  /// True when solve_in_place and solve_exact_in_place run on two threads: a CHOLMOD factor of 4 M entries or more
  /// whose elimination tree splits into two even groups of subtrees (detail/supernode_split.hpp). The result does
  /// not depend on the number of threads.
  bool parallel_solve() const;
  /// "cholmod" or "eigen-ldlt".
  std::string_view backend_name() const;

 private:
  void solve_in_place(double* b, int nrhs, SolvePrecision precision) const;

  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace hooke
