#pragma once
/// Constant-strain triangle (CST, Turner triangle), Lloyd et al. 2007, Eq. 3-5.
#include <hooke/core/types.hpp>
#include <hooke/material/material.hpp>

namespace hooke::fem {

/// 6 x 6 element stiffness K_CST, N/m, DOFs ordered (u1, v1, u2, v2, u3, v3) (Lloyd Eq. 3).
/// Blocks K_ik = t/(4A) [b_i b_k D11 + g_i g_k D33, b_i g_k D12 + g_i b_k D33; ...] with
/// b_i = y_j - y_k, g_i = x_k - x_j; for plane stress this is Eq. 4-5 verbatim.
/// @param nodes     3 x 2 node positions, m, counter-clockwise (A > 0)
/// @param material  E (Pa), nu, t (m), plane model; the law is ignored (linear)
/// @throws InvalidMesh if the triangle is clockwise or degenerate
Mat6 cst_stiffness(const Eigen::Matrix<double, 3, 2>& nodes, const material::Material& material);

}  // namespace hooke::fem
