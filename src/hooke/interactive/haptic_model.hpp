#pragma once
/// The probe's local model (multirate haptics: Cavusoglu & Tendick 2000; Mark et al. 1996): what the deformation
/// loop hands a haptic loop after each of its steps, so the haptic loop renders a force at its own rate (1 kHz)
/// from the device's position between two deformation steps: f(u) = force - stiffness (u - offset).
#include <hooke/core/error.hpp>
#include <hooke/core/types.hpp>
#include <string_view>

namespace hooke::interactive {

/// How the local model moves the force between two deformation steps: f(u) = f0 - K (u - u0) with K
enum class HapticStiffness {
  kNone,  ///< zero: the last step's force, held (zero-order hold)
  /// the condensed rest stiffness at the grabbed nodes (solve::contact_stiffness over LiveSettings::haptic_region,
  /// computed at the grab: exact when the region is the whole body, much stiffer when it is a part of it)
  kCondensed,
  /// refreshed at every deformation step from the body's own response: a symmetric secant (Powell-symmetric-
  /// Broyden) update K s = y with s the probe's move and y minus the force's change over the step, kept positive
  /// semidefinite; the condensed stiffness at the grab (docs/simulation.md: from zero it rendered the 11 k drag
  /// 10x worse at a 40 ms deformation step)
  kSecant,
};

/// "none", "condensed", "secant". @throws InvalidArgument otherwise
HapticStiffness haptic_stiffness_from_name(std::string_view name);
/// Stable name of `stiffness`.
std::string_view haptic_stiffness_name(HapticStiffness stiffness);

struct HapticModel {
  long version = 0;      ///< increases with every deformation step (0: no model yet)
  double time = 0.0;     ///< simulated time at the end of the step, s
  bool grabbed = false;  ///< the probe holds nodes (otherwise the force is zero)
  VecX offset;           ///< the probe's offset the step was taken with, m (dim)
  VecX force;            ///< the force the body exerted on the probe after the step, N (dim)
  /// the local stiffness at the held nodes, N/m (dim x dim, symmetric positive semidefinite; HapticStiffness)
  MatX stiffness;

  /// The force on the probe at offset u, N (dim): zero without a grab. @pre u has dim components
  VecX render(const VecX& u) const {
    if (!grabbed || force.size() != u.size()) return VecX::Zero(u.size());
    return force - stiffness * (u - offset);
  }
};

}  // namespace hooke::interactive
