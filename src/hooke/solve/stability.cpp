#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/core/sparse_cholesky.hpp>
#include <hooke/core/symmetric_eigen.hpp>
#include <hooke/solve/stability.hpp>
#include <random>

namespace hooke::solve {

double smallest_eigenvalue(const SparseMatrix& a, double relative_tolerance) {
  const Eigen::Index n = a.rows();
  if (n == 0) return 0.0;
  if (n <= 800) {
    const MatX dense = MatX(a);
    return symmetric_eigenvalues(dense)(0);
  }
  // Sylvester: a - t I is positive definite exactly when t < lambda_min. Bracket lambda_min between a shift
  // that factorises (lo) and one that does not (hi), then refine by inverse iteration shifted to lo.
  const double scale = a.diagonal().cwiseAbs().maxCoeff();
  SparseMatrix id(n, n);
  id.setIdentity();
  SparseCholesky chol;
  auto definite_below = [&](double t) { return chol.factorize(SparseMatrix(a - t * id)); };
  double hi = a.diagonal().minCoeff() + 1e-12 * scale;  // a Rayleigh quotient bounds lambda_min from above
  double lo = 0.0;
  if (definite_below(0.0)) {
    lo = 1e-14 * scale;
    if (!definite_below(lo)) return 0.0;  // positive definite, but singular to working precision
  } else {
    hi = 0.0;
    lo = -1e-8 * scale;
    for (int k = 0; !definite_below(lo); ++k) {
      if (k > 40) throw SolverFailure("smallest_eigenvalue: no shift made the matrix positive definite");
      hi = lo;
      lo *= 10.0;
    }
  }
  for (int k = 0; k < 80 && hi - lo > 1e-3 * std::max(std::abs(lo), std::abs(hi)); ++k) {
    const double mid = (lo > 0.0 && hi > 4.0 * lo)   ? std::sqrt(lo * hi)
                       : (hi < 0.0 && lo < 4.0 * hi) ? -std::sqrt(lo * hi)
                                                     : 0.5 * (lo + hi);
    if (definite_below(mid))
      lo = mid;
    else
      hi = mid;
  }
  if (!definite_below(lo)) throw SolverFailure("smallest_eigenvalue: lost the factorisation of the shifted matrix");
  std::mt19937 rng(12345);
  std::normal_distribution<double> normal;
  VecX v(n);
  for (Eigen::Index i = 0; i < n; ++i) v(i) = normal(rng);
  v.normalize();
  double rayleigh = v.dot(a * v), previous = std::numeric_limits<double>::infinity();
  for (int it = 0;
       it < 300 && std::abs(rayleigh - previous) > relative_tolerance * std::max(std::abs(rayleigh), 1e-14 * scale);
       ++it) {
    v = chol.solve(v);
    v.normalize();
    previous = rayleigh;
    rayleigh = v.dot(a * v);
  }
  return rayleigh;
}

}  // namespace hooke::solve
