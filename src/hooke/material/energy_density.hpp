#pragma once
/// Strain-energy density psi(F) (J/m^3), first Piola-Kirchhoff stress P = dpsi/dF (Pa) and its derivative
/// dP/dF (Pa), for the laws of material.hpp in 2D and 3D. dP/dF is a (d*d) x (d*d) matrix acting on
/// column-major vec(F): entry (i + d j, k + d l) is dP_ij / dF_kl.
#include <hooke/core/types.hpp>
#include <hooke/material/material.hpp>

namespace hooke::material {

using Mat4 = Eigen::Matrix4d;
using Mat9 = Eigen::Matrix<double, 9, 9>;

/// psi(F), J/m^3. +infinity for the Neo-Hookean law when det F <= 0 (an inverted element).
double energy_density(Law law, const Mat2& deformation_gradient, const Lame& lame);
/// @copydoc energy_density(Law, const Mat2&, const Lame&)
double energy_density(Law law, const Mat3& deformation_gradient, const Lame& lame);

/// P = dpsi/dF, Pa. @pre for the Neo-Hookean law, det F > 0
Mat2 first_piola(Law law, const Mat2& deformation_gradient, const Lame& lame);
/// @copydoc first_piola(Law, const Mat2&, const Lame&)
Mat3 first_piola(Law law, const Mat3& deformation_gradient, const Lame& lame);

/// dP/dF, Pa, as a (d*d) x (d*d) matrix on column-major vec(F). @pre for the Neo-Hookean law, det F > 0
Mat4 first_piola_derivative(Law law, const Mat2& deformation_gradient, const Lame& lame);
/// @copydoc first_piola_derivative(Law, const Mat2&, const Lame&)
Mat9 first_piola_derivative(Law law, const Mat3& deformation_gradient, const Lame& lame);

}  // namespace hooke::material
