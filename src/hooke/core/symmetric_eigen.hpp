#pragma once
/// Eigenvalues and eigenvectors of dense symmetric matrices, compiled once: Eigen's solver costs about 14 s of
/// compilation per matrix type and translation unit under the sanitizers, so the library's and tests' callers share
/// these instead of instantiating it (docs/architecture.md, "Build time").
#include <hooke/core/types.hpp>

namespace hooke {

/// The eigenvalues of the symmetric matrix `a` (its lower triangle is read), ascending, in a's units.
/// @pre a is square
VecX symmetric_eigenvalues(const Eigen::Ref<const MatX>& a);

/// Eigenvalues (ascending) and the matching orthonormal eigenvectors (columns) of a symmetric matrix.
struct SymmetricEigen {
  VecX values;
  MatX vectors;
};

/// The eigen-decomposition of the symmetric matrix `a` (its lower triangle is read). @pre a is square
SymmetricEigen symmetric_eigen(const Eigen::Ref<const MatX>& a);

}  // namespace hooke
