#pragma once
// Projection of a small symmetric matrix onto the positive semi-definite cone (negative eigenvalues -> 0).
#include <Eigen/Eigenvalues>

namespace hooke::detail {

template <typename Matrix>
void project_to_psd(Matrix& m) {
  Eigen::SelfAdjointEigenSolver<Matrix> eig(m);
  if (eig.eigenvalues().minCoeff() >= 0.0) return;
  auto values = eig.eigenvalues().cwiseMax(0.0).eval();
  m = eig.eigenvectors() * values.asDiagonal() * eig.eigenvectors().transpose();
}

}  // namespace hooke::detail
