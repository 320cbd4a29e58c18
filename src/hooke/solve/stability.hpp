#pragma once
/// Stability of an equilibrium: the smallest eigenvalue of the tangent stiffness on the free DOFs.
#include <hooke/core/types.hpp>

namespace hooke::solve {

/// Smallest eigenvalue of the symmetric matrix `a` (N/m for a stiffness matrix). Dense eigensolver up to
/// 800 rows; above, inverse iteration on a + sigma I factorised by CHOLMOD, with the smallest sigma >= 0
/// (found by growing it tenfold from 1e-8 max|diag|) that makes it positive definite.
/// @param relative_tolerance  stop when the Rayleigh quotient changes by less than this (relative)
/// @pre a is square and symmetric (both triangles stored)
double smallest_eigenvalue(const SparseMatrix& a, double relative_tolerance = 1e-9);

}  // namespace hooke::solve
