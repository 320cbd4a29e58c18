#pragma once
/// Linear 4-node tetrahedron (constant strain), Lloyd et al. 2007, App. B.
#include <hooke/core/types.hpp>
#include <hooke/material/material.hpp>

namespace hooke::fem {

/// 12 x 12 element stiffness K = B^T D B V, N/m (Lloyd App. B), DOFs (u1, v1, w1, ..., u4, v4, w4).
/// B follows from the shape functions N = [1 1 1 1; x; y; z]^-1 [1; x; y; z] and the strain ordering
/// (eps_xx, eps_yy, eps_zz, gamma_xy, gamma_yz, gamma_zx).
/// @param nodes     4 x 3 node positions, m, positive volume
/// @param material  E (Pa), nu; the law is ignored (linear)
/// @throws InvalidMesh if the volume is not positive
Mat12 tet4_stiffness(const Eigen::Matrix<double, 4, 3>& nodes, const material::Material& material);

/// Shape-function gradients dN_a/dX (row a, 1/m) of a tet; returns its signed volume, m^3.
double tet4_gradients(const Eigen::Matrix<double, 4, 3>& nodes, Eigen::Matrix<double, 4, 3>& gradients);

}  // namespace hooke::fem
