#pragma once
/// The split of an isotropic material into the part a central-spring network can carry and a volumetric
/// remainder (docs/methods/any_nu.md). A network of linearised central springs has the energy
/// sum_s k_s l_s^2 (n_s . eps n_s)^2 / 2, a fully symmetric tensor: isotropic on average only with lambda = mu
/// (Cauchy's relation, nu = 1/4 in 3D). A volume term E_V = k_V (V - V0)^2 / (2 V0^2) linearises to
/// k_V (tr eps)^2 / 2 (delta V = V0 tr eps), a pure lambda term. So springs calibrated for (E_s, nu = 1/4) with
/// E_s = 5 mu / 2 carry mu and a lambda of mu; a volume term with k_V = (lambda - mu) V0 carries the rest.
/// Below nu = 1/4 that k_V is negative, and measured on the cylinder with a hole it makes the assembled stiffness
/// indefinite for nu <= 0.15 and less accurate than springs alone for nu < 1/4; there the split is springs only at
/// (E, nu = 1/4), Lloyd's Eq. 12 choice (docs/methods/any_nu.md).
#include <hooke/material/material.hpp>

namespace hooke::calibrate {

struct CauchySplit {
  double spring_youngs_modulus = 0.0;  ///< E_s, Pa: the springs are those of a nu = 1/4 material of modulus E_s
  double volume_lambda = 0.0;          ///< lambda_V, Pa: the volume terms carry lambda_V (tr eps)^2 / 2, >= 0
};

/// The split of a 3D material (E in Pa > 0, -1 < nu < 0.5), Lamé parameters of material::lame():
/// nu >= 1/4: E_s = 5 mu / 2, lambda_V = lambda - mu; nu < 1/4: E_s = E, lambda_V = 0. Continuous at nu = 1/4,
/// where E_s = E and lambda_V = 0 (to round-off).
[[nodiscard]] CauchySplit cauchy_split(const material::Material& material);

/// The split of a 2D material (plane stress or strain by material.plane; Lamé parameters of
/// material::lame(material, 2)). A network of central springs in the plane is isotropic on average only with
/// lambda* = mu (nu = 1/3 in plane stress, the value Lloyd's Eq. 9 is derived for); an area term
/// k_A (A - A0)^2 / (2 A0^2) linearises to k_A (tr eps)^2 / 2 (delta A = A0 tr eps). So: lambda* >= mu: springs of
/// Eq. 9 at E_s = 8 mu / 3 (the modulus of the nu = 1/3 plane-stress material with shear modulus mu) and
/// lambda_A = lambda* - mu (the volume_lambda field); lambda* < mu: E_s = E, lambda_A = 0 (Eq. 9 alone). Continuous
/// at nu = 1/3 in plane stress; in plane strain the threshold is nu = 1/4, where the springs jump from E to 16 E / 15.
[[nodiscard]] CauchySplit cauchy_split_2d(const material::Material& material);

/// The unclamped split E_s = 5 mu / 2, lambda_V = lambda - mu for any nu (negative lambda_V below 1/4): for
/// studies of where negative volume terms lose definiteness (tets_without_definite_share).
[[nodiscard]] CauchySplit unclamped_cauchy_split(const material::Material& material);

}  // namespace hooke::calibrate
