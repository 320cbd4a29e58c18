#pragma once
/// Stability of an equilibrium: the smallest eigenvalue of the tangent stiffness on the free DOFs.
#include <hooke/core/types.hpp>

namespace hooke::solve {

/// Smallest eigenvalue of the symmetric matrix `a` (N/m for a stiffness matrix). Dense eigensolver up to
/// 800 rows; above, the shift t with a - t I just positive definite is bracketed by Cholesky attempts
/// (Sylvester's law of inertia) to 1e-3 relative, then refined by inverse iteration shifted there.
/// @param relative_tolerance  stop when the Rayleigh quotient changes by less than this (relative)
/// @pre a is square and symmetric (both triangles stored)
double smallest_eigenvalue(const SparseMatrix& a, double relative_tolerance = 1e-9);

}  // namespace hooke::solve
