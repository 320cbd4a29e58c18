#include <hooke/core/name_table.hpp>
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

namespace {
constexpr NameTable<Law, 3> kLaws{"material law",
                                  {{{Law::kLinear, "linear"}, {Law::kStVK, "stvk"}, {Law::kNeoHookean, "neohookean"}}}};
constexpr NameTable<Plane, 2> kPlanes{"plane", {{{Plane::kStress, "stress"}, {Plane::kStrain, "strain"}}}};
}  // namespace

Law law_from_name(std::string_view name) { return kLaws.from_name(name); }
std::string_view law_name(Law law) { return kLaws.name(law); }
Plane plane_from_name(std::string_view name) { return kPlanes.from_name(name); }
std::string_view plane_name(Plane plane) { return kPlanes.name(plane); }

}  // namespace hooke::material
