#pragma once
/// Isotropic elastic materials: linear (small strain), St. Venant-Kirchhoff, compressible Neo-Hookean.
#include <string>
#include <string_view>

namespace hooke::material {

/// Constitutive law. Stable names: "linear", "stvk", "neohookean".
enum class Law {
  kLinear,     ///< small-strain linear elasticity, psi = mu eps:eps + lambda/2 tr(eps)^2, eps = sym(F) - I
  kStVK,       ///< St. Venant-Kirchhoff: the same law in the Green-Lagrange strain E = (F^T F - I)/2
  kNeoHookean  ///< compressible Neo-Hookean: psi = mu/2 (tr F^T F - d) - mu ln J + lambda/2 (ln J)^2
};

/// 2D reduction of a 3D body.
enum class Plane {
  kStress,  ///< thin plate, sigma_zz = 0 (Lloyd et al. 2007, App. A)
  kStrain   ///< long prism, eps_zz = 0
};

/// One isotropic material.
struct Material {
  Law law = Law::kLinear;        ///< constitutive law
  double youngs_modulus = 0.0;   ///< E, Pa, > 0
  double poisson_ratio = 0.0;    ///< nu, in (-1, 0.5)
  Plane plane = Plane::kStress;  ///< 2D meshes only
  double thickness = 1.0;        ///< t, m, > 0; 2D meshes only (plate thickness for plane stress)

  bool operator==(const Material&) const = default;
};

/// Lamé parameters, Pa.
struct Lame {
  double lambda = 0.0;  ///< first Lamé parameter
  double mu = 0.0;      ///< shear modulus
};

/// Checks E > 0, -1 < nu < 0.5, t > 0 (all finite).
/// @throws InvalidMaterial with the offending value and its valid range
void validate(const Material& material);

/// 3D Lamé parameters: lambda = E nu / ((1 + nu)(1 - 2 nu)), mu = E / (2 (1 + nu)).
Lame lame(double youngs_modulus, double poisson_ratio);

/// Lamé parameters of the 2D law for `dim` = 2 (plane stress uses lambda* = E nu / (1 - nu^2), so that the
/// 2D laws linearise to the plane-stress relation of Lloyd App. A) or the 3D ones for `dim` = 3.
Lame lame(const Material& material, int dim);

/// Parses "linear", "stvk", "neohookean". @throws InvalidArgument naming the valid names
Law law_from_name(std::string_view name);
/// Stable name of `law`.
std::string_view law_name(Law law);

/// Parses "stress", "strain". @throws InvalidArgument naming the valid names
Plane plane_from_name(std::string_view name);
/// Stable name of `plane`: "stress" or "strain".
std::string_view plane_name(Plane plane);

}  // namespace hooke::material
