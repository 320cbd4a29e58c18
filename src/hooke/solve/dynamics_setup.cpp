#include <charconv>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/core/settings.hpp>
#include <hooke/solve/dynamics_setup.hpp>
#include <string>
#include <utility>

namespace hooke::solve {
namespace {

constexpr DynamicsField kDynamicsFields[] = {
    {"dt", "Time step, s (the viewer runs one step per dt of wall time)", &DynamicsSetup::dt, nullptr},
    {"gravity", "Gravity 9.81 m/s^2 down the vertical axis (y in 2D, z in 3D)", nullptr, &DynamicsSetup::gravity},
    {"damping-mass", "Rayleigh alpha, 1/s", &DynamicsSetup::damping_mass, nullptr},
    {"damping-stiffness", "Rayleigh beta, s", &DynamicsSetup::damping_stiffness, nullptr},
    {"influence-radius",
     "surface: radius of influence of the probe's interaction weights (Eq. 4), m (0: half the bounding-box diagonal)",
     &DynamicsSetup::influence_radius, nullptr},
};

}  // namespace

std::span<const DynamicsField> dynamics_fields() { return kDynamicsFields; }

double setting_number(std::string_view name, std::string_view text) {
  return settings::parse_number("set " + std::string(name), text);
}

bool setting_flag(std::string_view name, std::string_view text) {
  return settings::parse_flag("set " + std::string(name), text);
}

bool set_dynamics_field(DynamicsSetup& setup, std::string_view name, std::string_view text) {
  for (const DynamicsField& f : kDynamicsFields) {
    if (f.name != name) continue;
    if (f.number)
      setup.*f.number = setting_number(name, text);
    else
      setup.*f.flag = setting_flag(name, text);
    return true;
  }
  return false;
}

void validate(const DynamicsSetup& s) {
  if (!(s.dt > 0.0) || !std::isfinite(s.dt)) throw InvalidArgument("the time step dt must be a finite number > 0 s");
  if (!(s.damping_mass >= 0.0) || !(s.damping_stiffness >= 0.0) || !std::isfinite(s.damping_mass) ||
      !std::isfinite(s.damping_stiffness))
    throw InvalidArgument("the Rayleigh damping coefficients must be finite and >= 0");
  if (!(s.influence_radius >= 0.0) || !std::isfinite(s.influence_radius))
    throw InvalidArgument("the radius of influence must be finite and >= 0 m");
}

Dynamics make_dynamics(const DynamicsSetup& s, VecX mass, int dim) {
  Dynamics d{std::move(mass), VecX(), s.damping_mass, s.damping_stiffness};
  if (s.gravity) {
    d.gravity = VecX::Zero(dim);
    d.gravity(dim - 1) = -9.81;  // along -y in 2D, -z in 3D: the meshes' vertical axis
  }
  return d;
}

double influence_radius(const DynamicsSetup& s, double bounding_box_diagonal) {
  return s.influence_radius > 0.0 ? s.influence_radius : 0.5 * bounding_box_diagonal;
}

}  // namespace hooke::solve
