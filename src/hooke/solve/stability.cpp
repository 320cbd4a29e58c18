#include <Eigen/Eigenvalues>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/solve/sparse_cholesky.hpp>
#include <hooke/solve/stability.hpp>
#include <random>

namespace hooke::solve {

double smallest_eigenvalue(const SparseMatrix& a, double relative_tolerance) {
  const Eigen::Index n = a.rows();
  if (n == 0) return 0.0;
  if (n <= 800) {
    const MatX dense = MatX(a);
    Eigen::SelfAdjointEigenSolver<MatX> eig(dense, Eigen::EigenvaluesOnly);
    return eig.eigenvalues()(0);
  }
  const double scale = a.diagonal().cwiseAbs().maxCoeff();
  SparseMatrix id(n, n);
  id.setIdentity();
  SparseCholesky chol;
  double sigma = 0.0;
  bool ok = chol.factorize(a);
  for (int attempt = 0; !ok && attempt < 40; ++attempt) {
    sigma = sigma == 0.0 ? 1e-8 * scale : sigma * 10.0;
    ok = chol.factorize(SparseMatrix(a + sigma * id));
  }
  if (!ok) throw SolverFailure("smallest_eigenvalue: no shift made the matrix positive definite");
  std::mt19937 rng(12345);
  std::normal_distribution<double> normal;
  VecX v(n);
  for (Eigen::Index i = 0; i < n; ++i) v(i) = normal(rng);
  v.normalize();
  double rayleigh = v.dot(a * v), previous = std::numeric_limits<double>::infinity();
  for (int it = 0; it < 500 && std::abs(rayleigh - previous) > relative_tolerance * std::max(std::abs(rayleigh), 1e-30 * scale); ++it) {
    v = chol.solve(v);
    v.normalize();
    previous = rayleigh;
    rayleigh = v.dot(a * v);
  }
  return rayleigh;
}

}  // namespace hooke::solve
