#pragma once
/// The probe's local model (multirate haptics: Cavusoglu & Tendick 2000; Mark et al. 1996): what the deformation
/// loop hands a haptic loop after each of its steps, so the haptic loop renders a force at its own rate (1 kHz)
/// from the device's position between two deformation steps: f(u) = force - stiffness (u - offset) - curvature (u -
/// offset, u - offset) / 2.
#include <hooke/core/error.hpp>
#include <hooke/core/types.hpp>
#include <hooke/interactive/local_contact.hpp>
#include <memory>
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

/// The quasi-Newton tolerance (solve::QuasiNewtonOptions::tolerance) of a multirate deformation step, by default
/// (the viewer's --haptic-rate, hooke bench --haptics): the haptic loop renders from the step's probe force, and
/// after a long step the integrator's real-time default 1e-2 leaves it 7 % off the converged one (the 11 425-node
/// bench cylinder, 1 mm drag in one 0.5 s step: 0.0280 against 0.0262 N); 1e-3 is within 0.1 % for one more
/// iteration (docs/simulation.md, multirate haptics).
inline constexpr double kDeformationTolerance = 1e-3;

/// T(s): the stiffness' change per offset s, N/m (dim x dim; (T(s))(c, a) = sum_b T(c, a dim + b) s_b) for a
/// curvature T (dim x dim^2, HapticModel::curvature). @pre s has T.rows() components
MatX curvature_along(const MatX& curvature, const VecX& s);

struct HapticModel {
  long version = 0;      ///< increases with every deformation step (0: no model yet)
  double time = 0.0;     ///< simulated time at the end of the step, s
  bool grabbed = false;  ///< the probe holds nodes (otherwise the force is zero)
  VecX offset;           ///< the probe's offset the step was taken with, m (dim)
  VecX force;            ///< the force the body exerted on the probe after the step, N (dim)
  /// the local stiffness at the held nodes, N/m (dim x dim, symmetric positive semidefinite; HapticStiffness)
  MatX stiffness;
  /// the condensed energy's third derivative at the grab, N/m^2 (dim x dim^2, solve::contact_curvature; empty:
  /// the model is linear in the offset, when LiveSettings::haptic_curvature is off or an element of the body
  /// inverts within the difference step at the grab)
  MatX curvature;
  /// A pressing tool's local contact model after the step (null: no tool, or a grab, which the device drives
  /// instead). The device's offset then moves the tool from `tool_origin` (LiveSimulation::drive_tool), and
  /// `offset` is the one the step was taken with. With HapticStiffness::kNone a tool's force is held instead
  /// (`tool` set, `contact` null).
  std::shared_ptr<const LocalContact> contact;
  bool tool = false;          ///< a tool without a grab: `force` and `offset` are the tool's
  contact::Pose tool_origin;  ///< where the device's zero puts the tool

  /// The force on the probe, or on the tool, at the device's offset u, N (dim): the grab's local model, or the
  /// tool's contact model at tool_origin + u (3D), or the held force; zero with neither grab nor tool.
  /// @pre u has dim components
  VecX render(const VecX& u) const {
    if (!grabbed && contact && u.size() == 3) return contact->force({tool_origin.position + u, tool_origin.rotation});
    if ((!grabbed && !tool) || force.size() != u.size()) return VecX::Zero(u.size());
    const VecX d = u - offset;
    VecX f = force - stiffness * d;
    if (curvature.rows() == d.size())  // T(d, d) = sum_a d_a T_a d, T_a the a-th dim x dim block
      for (Eigen::Index a = 0; a < d.size(); ++a) f -= 0.5 * d(a) * (curvature.middleCols(a * d.size(), d.size()) * d);
    return f;
  }
};

}  // namespace hooke::interactive
