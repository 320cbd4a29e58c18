#pragma once
/// Elasticity matrices D of isotropic linear elasticity in Voigt notation (engineering shear strains).
#include <hooke/core/types.hpp>
#include <hooke/material/material.hpp>

namespace hooke::material {

/// 3 x 3 plane matrix D with sigma = D (eps_xx, eps_yy, gamma_xy), Pa (Lloyd et al. 2007, App. A for
/// plane stress; the plane-strain form when material.plane is kStrain). @pre validate(material) passes
Mat3 elasticity_matrix_2d(const Material& material);

/// 6 x 6 matrix D with sigma = D (eps_xx, eps_yy, eps_zz, gamma_xy, gamma_yz, gamma_zx), Pa
/// (Lloyd et al. 2007, App. B strain ordering). @pre validate(material) passes
Mat6 elasticity_matrix_3d(const Material& material);

}  // namespace hooke::material
