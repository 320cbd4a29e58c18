#pragma once
// The interactive viewer's window: a PhysicsLoop in its own thread, drawn at the display's rate with GLFW, OpenGL
// 3.3 and Dear ImGui; the mouse as a probe; scripted, headless runs for tests and demos.
#include <hooke/calibrate/calibrated_model.hpp>
#include <hooke/interactive/live_simulation.hpp>
#include <hooke/interactive/script.hpp>
#include <string>
#include <vector>

namespace hooke::viewer {

struct ViewerOptions {
  calibrate::CalibratedModel model;                ///< what to simulate (a model file or a fresh calibration)
  interactive::LiveSettings settings;              ///< method "file": run `model` as it is
  std::vector<interactive::ScriptCommand> script;  ///< timed interactions (empty: none)
  std::string screenshot;                          ///< PNG of the last frame, written at exit (empty: none)
  int frames = 0;                                  ///< exit after this many drawn frames (0: when the window closes)
  std::string stats;                               ///< JSON of the rates and the probe force, written at exit
  std::string save_model;                          ///< the model being simulated at exit (a model file; empty: none)
  std::string record;                              ///< folder for a ParaView series of the drawn frames (empty: none)
  int width = 1024, height = 768;                  ///< window size, pixels
  std::string colormap = "displacement";           ///< initial colour map
  double grab_radius = 0.0;                        ///< m
  bool no_panel = false;                           ///< hide the panel (overlays stay)
  int threads = 1;                                 ///< OpenMP threads of the physics (>= 1)
  bool realtime = true;                            ///< physics at one step per dt of wall time (else as fast as it can)
  /// multirate haptics: a haptic loop at this rate renders the probe force from the deformation's local model and
  /// the mouse drives it (0: off, the mouse drags the physics directly), Hz
  double haptic_rate = 0.0;
};

/// Opens the window and runs until it closes, --frames are drawn or the script quits. Returns the exit code.
/// @throws Error when no display or OpenGL 3.3 context is available (the message points to xvfb-run), IoError when
///   a screenshot, the stats or the series cannot be written
int run_viewer(const ViewerOptions& options);

}  // namespace hooke::viewer
