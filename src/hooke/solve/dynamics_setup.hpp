#pragma once
/// How a run's dynamics are set up around a model, whoever runs it: `hooke simulate` (solve::SimulationOptions),
/// the viewer and Python's live simulation (interactive::LiveSettings). One struct, one range check, one builder.
#include <hooke/core/types.hpp>
#include <hooke/solve/simulator.hpp>
#include <span>
#include <string_view>

namespace hooke::solve {

struct DynamicsSetup {
  double dt = 1e-3;                ///< time step, s (> 0): 1 kHz, a haptic loop's rate
  bool gravity = false;            ///< 9.81 m/s^2 down the vertical axis (y in 2D, z in 3D)
  double damping_mass = 0.0;       ///< Rayleigh alpha, 1/s (>= 0)
  double damping_stiffness = 0.0;  ///< Rayleigh beta, s (>= 0)
  double influence_radius = 0.0;   ///< surface model: r of Eq. 4, m (>= 0; 0: half the bounding-box diagonal)

  bool operator==(const DynamicsSetup&) const = default;
};

/// One field of DynamicsSetup that users set by name: `hooke simulate` and `hooke view` take it as --NAME, the
/// viewer's scripts as `set NAME VALUE`, Python as NAME=VALUE (dashes as underscores). Adding a field to the setup
/// and a row to dynamics_fields() is all a new setting needs.
struct DynamicsField {
  std::string_view name;                    ///< "dt", "gravity", "damping-mass", ...
  std::string_view help;                    ///< one line, with the unit
  double DynamicsSetup::*number = nullptr;  ///< a number field, or
  bool DynamicsSetup::*flag = nullptr;      ///< an on/off field
};
/// Every user-settable field of DynamicsSetup, in the order --help lists them.
std::span<const DynamicsField> dynamics_fields();

/// `text` as a finite number for setting `name`. @throws InvalidArgument ("set NAME: 'TEXT' is not a finite number")
double setting_number(std::string_view name, std::string_view text);
/// `text` ("on" or "off") as a flag for setting `name`. @throws InvalidArgument ("set NAME takes on or off, not
/// 'TEXT'")
bool setting_flag(std::string_view name, std::string_view text);

/// Sets the field of `setup` named `name` from `text`: "on" or "off" for a flag, a finite number otherwise (ranges
/// are validate()'s). @return false when no field has that name. @throws InvalidArgument for a malformed value
bool set_dynamics_field(DynamicsSetup& setup, std::string_view name, std::string_view text);

/// @throws InvalidArgument naming the field when dt is not a finite number > 0, a damping coefficient or the radius
///   is negative or not finite
void validate(const DynamicsSetup& setup);

/// The simulator's Dynamics for lumped masses `mass` (kg per DOF) in `dim` dimensions: the Rayleigh coefficients,
/// and gravity -9.81 m/s^2 along the last axis when setup.gravity is set (empty otherwise).
Dynamics make_dynamics(const DynamicsSetup& setup, VecX mass, int dim);

/// Eq. 4's radius of influence (Arnab & Raja), m: setup.influence_radius, or half of `bounding_box_diagonal` (m)
/// when it is 0.
double influence_radius(const DynamicsSetup& setup, double bounding_box_diagonal);

}  // namespace hooke::solve
