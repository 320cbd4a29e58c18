#include <hooke/material/material.hpp>

#include <cmath>
#include <hooke/core/error.hpp>
#include <sstream>

namespace hooke::material {

void validate(const Material& m) {
  auto fail = [](const std::string& what) { throw InvalidMaterial(what); };
  std::ostringstream value;
  if (!std::isfinite(m.youngs_modulus) || m.youngs_modulus <= 0.0) {
    value << m.youngs_modulus;
    fail("Young's modulus must be a positive number of pascals, got " + value.str());
  }
  if (!std::isfinite(m.poisson_ratio) || m.poisson_ratio <= -1.0 || m.poisson_ratio >= 0.5) {
    value << m.poisson_ratio;
    fail("Poisson's ratio must lie in (-1, 0.5), got " + value.str() +
         (m.poisson_ratio >= 0.5 ? " (0.5 is incompressible, which these models cannot represent)" : ""));
  }
  if (!std::isfinite(m.thickness) || m.thickness <= 0.0) {
    value << m.thickness;
    fail("thickness must be a positive number of metres, got " + value.str());
  }
}

Lame lame(double youngs_modulus, double poisson_ratio) {
  const double e = youngs_modulus, nu = poisson_ratio;
  return {e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), e / (2.0 * (1.0 + nu))};
}

Lame lame(const Material& m, int dim) {
  Lame l = lame(m.youngs_modulus, m.poisson_ratio);
  if (dim == 2 && m.plane == Plane::kStress) {
    const double nu = m.poisson_ratio;
    l.lambda = m.youngs_modulus * nu / (1.0 - nu * nu);
  }
  return l;
}

Law law_from_name(std::string_view name) {
  if (name == "linear") return Law::kLinear;
  if (name == "stvk") return Law::kStVK;
  if (name == "neohookean") return Law::kNeoHookean;
  throw InvalidArgument("unknown material law '" + std::string(name) + "' (use linear, stvk or neohookean)");
}

Plane plane_from_name(std::string_view name) {
  if (name == "stress") return Plane::kStress;
  if (name == "strain") return Plane::kStrain;
  throw InvalidArgument("unknown plane '" + std::string(name) + "' (use stress or strain)");
}

std::string_view plane_name(Plane plane) { return plane == Plane::kStress ? "stress" : "strain"; }

std::string_view law_name(Law law) {
  switch (law) {
    case Law::kLinear: return "linear";
    case Law::kStVK: return "stvk";
    case Law::kNeoHookean: return "neohookean";
  }
  return "unknown";
}

}  // namespace hooke::material
