#pragma once
// What the viewer's window shows and the panel edits (the drawing side's state; the physics has its own).
#include <deque>
#include <hooke/interactive/fields.hpp>
#include <hooke/interactive/haptic_loop.hpp>
#include <hooke/interactive/live_simulation.hpp>
#include <optional>
#include <string>

namespace hooke::viewer {

enum class Ghost { kOff, kLinear, kStVK };

struct ViewState {
  interactive::ColorField field = interactive::ColorField::kDisplacement;
  Ghost ghost = Ghost::kOff;
  std::optional<VecX> ghost_positions;  ///< the FEM static solution under the probe, flat, m
  VecX ghost_force;                     ///< its holding force, N
  std::string ghost_message;            ///< how the last ghost solve went
  std::string setting_error;            ///< why the last model setting typed in the panel was refused
  interactive::LiveSettings edit;       ///< what the panel edits; applied on release of a slider
  /// the tissue the E and nu sliders edit: -1 the regions not listed (edit.material), else an index into
  /// edit.model.regions (docs/regions.md)
  int tissue = -1;
  double grab_radius = 0.0;  ///< nodes within this distance of the picked point are grabbed too, m
  /// (sim time, |F| in N) over the last 5 s: the probe's force, or the tool's while a tool presses
  std::deque<std::pair<double, float>> force_history;
  double draw_rate = 0.0;  ///< frames per second of wall time
  /// the haptic loop's rates and force (multirate haptics, --haptic-rate; haptic.target_rate 0: off)
  interactive::HapticStats haptic;
  VecX haptic_force;                        ///< N
  double colour_lo = 0.0, colour_hi = 1.0;  ///< the colour bar's range, in the field's unit
  bool paused = false;
  /// What the left mouse button does: grab nodes and drive them, or press with a rigid tool (docs/contact.md)
  bool press_mode = false;
  double tool_radius = 0.0;    ///< the pressing sphere's radius, m (0: 5 % of the scene's size)
  double tool_friction = 0.0;  ///< its Coulomb coefficient
};

/// What the user asked for in the panel this frame.
struct PanelRequests {
  bool apply_settings = false;  ///< ViewState::edit changed: re-calibrate / rebuild
  bool reset = false;
  bool toggle_pause = false;
  bool solve_ghost = false;
};

}  // namespace hooke::viewer
