#pragma once
/// Bilinear 4-node quadrilateral (Q4), iso-parametric, 2 x 2 Gauss quadrature.
#include <hooke/core/types.hpp>
#include <hooke/material/material.hpp>

namespace hooke::fem {

/// 8 x 8 element stiffness, N/m, K = t sum_q w_q B_q^T D B_q det J_q, DOFs (u1, v1, ..., u4, v4).
/// Exact for parallelograms (the integrand is then polynomial of degree 2 in each direction).
/// @param nodes     4 x 2 node positions, m, counter-clockwise, convex
/// @param material  E (Pa), nu, t (m), plane model; the law is ignored (linear)
/// @throws InvalidMesh where the Jacobian is not positive at a Gauss point
Mat8 quad4_stiffness(const Eigen::Matrix<double, 4, 2>& nodes, const material::Material& material);

/// Shape-function gradients dN/dX (4 x 2, 1/m) and Jacobian determinant (m^2) of the bilinear map at the
/// reference point (xi, eta) in [-1, 1]^2.
/// @return the determinant; `gradients` receives dN_a/dX in row a
double quad4_gradients(const Eigen::Matrix<double, 4, 2>& nodes, double xi, double eta,
                       Eigen::Matrix<double, 4, 2>& gradients);

}  // namespace hooke::fem
