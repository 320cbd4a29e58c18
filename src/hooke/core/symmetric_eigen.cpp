// The one translation unit that instantiates Eigen's symmetric eigen-solver (core/symmetric_eigen.hpp), for
// element-sized matrices (at most 12 x 12, without heap allocation) and for any size.
#include <Eigen/Eigenvalues>
#include <hooke/core/detail/psd.hpp>
#include <hooke/core/symmetric_eigen.hpp>

namespace hooke {
namespace {
using Small =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, detail::kMaxPsdSize, detail::kMaxPsdSize>;
}  // namespace

VecX symmetric_eigenvalues(const Eigen::Ref<const MatX>& a) {
  if (a.rows() <= detail::kMaxPsdSize)
    return Eigen::SelfAdjointEigenSolver<Small>(Small(a), Eigen::EigenvaluesOnly).eigenvalues();
  return Eigen::SelfAdjointEigenSolver<MatX>(a, Eigen::EigenvaluesOnly).eigenvalues();
}

SymmetricEigen symmetric_eigen(const Eigen::Ref<const MatX>& a) {
  const Eigen::SelfAdjointEigenSolver<MatX> eig(a);
  return {eig.eigenvalues(), eig.eigenvectors()};
}

void detail::project_to_psd(double* m, int n) {
  Eigen::Map<MatX> map(m, n, n);
  const Eigen::SelfAdjointEigenSolver<Small> eig{Small(map)};
  if (eig.eigenvalues().minCoeff() >= 0.0) return;
  const auto values = eig.eigenvalues().cwiseMax(0.0).eval();
  map = eig.eigenvectors() * values.asDiagonal() * eig.eigenvectors().transpose();
}

}  // namespace hooke
