// hooke view (MESH --young PA --poisson NU --method NAME | --model MODEL.json) [--integrator ...] [--dt S]
// [--script FILE] [--screenshot FILE.png] [--frames N] [--stats FILE.json] [--record DIR]
#include "view_command.hpp"

#include <cmath>
#include <commands.hpp>
#include <hooke/core/error.hpp>
#include <hooke/interactive/fields.hpp>
#include <hooke/interactive/live_simulation.hpp>
#include <hooke/interactive/script.hpp>
#include <memory>

#include "viewer.hpp"

namespace hooke::viewer {
namespace {

struct ViewCli {
  cli::ModelSource in;
  cli::IntegratorInput integrator;
  std::string script, colormap = "displacement";
  interactive::LiveSettings settings;
  ViewerOptions run;
  bool fast = false;
  std::vector<int> size{1024, 768};
  std::string haptic_stiffness_name = "secant";
};

int run_view(ViewCli o) {
  // Everything is checked before a window opens: the model, the settings, the script, the colour map.
  ViewerOptions v = o.run;
  v.model = cli::load_model(o.in);
  // A calibration keeps its method's name ("auto" re-picks when nu changes); a model file runs as it is and is remade
  // by its own method when the sliders change its material (interactive::live_method_for; "file" when hooke cannot).
  const calibrate::ModelOptions given = cli::calibration_settings(o.in).model;
  v.settings.model = given;
  v.settings.model.method = o.in.model_path.empty() ? given.method : interactive::live_method_for(v.model);
  v.settings.material = v.model.material;
  v.settings.model.density = v.model.density;
  v.settings.model.regions = v.model.regions;  // the sliders change the material of the regions not listed
  v.settings.simulator = o.settings.simulator;
  // Multirate: the haptic loop renders from each deformation step's probe force, so it is converged further.
  if (v.haptic_rate > 0.0) v.settings.simulator.quasi_newton.tolerance = interactive::kDeformationTolerance;
  cli::apply_integrator_options(o.integrator, v.settings.simulator);
  v.settings.dynamics = o.settings.dynamics;
  interactive::LiveSimulation check(v.model, v.settings);  // a model the integrator cannot run fails here
  (void)check;
  if (!o.script.empty()) v.script = interactive::read_script(o.script);
  interactive::color_field_from_name(o.colormap);
  v.colormap = o.colormap;
  if (o.size.size() != 2 || o.size[0] < 64 || o.size[1] < 64 || o.size[0] > 8192 || o.size[1] > 8192)
    throw InvalidArgument("--window-size takes WIDTH,HEIGHT in pixels, each in [64, 8192]");
  v.width = o.size[0];
  v.height = o.size[1];
  v.realtime = !o.fast;
  v.settings.haptic_stiffness = interactive::haptic_stiffness_from_name(o.haptic_stiffness_name);
  v.settings.haptic_curvature = o.settings.haptic_curvature;
  if (!(v.haptic_rate >= 0.0) || !std::isfinite(v.haptic_rate)) throw InvalidArgument("--haptic-rate must be >= 0 Hz");
  if (v.threads < 1) throw InvalidArgument("--threads must be >= 1");
  if (v.grab_radius < 0.0) throw InvalidArgument("--grab-radius must be >= 0 m");
  if (v.frames < 0) throw InvalidArgument("--frames must be >= 0");
  return run_viewer(v);
}

}  // namespace

std::function<int()> add_view_options(CLI::App* cmd) {
  auto o = std::make_shared<ViewCli>();
  cli::add_model_source_options(cmd, o->in, settings::kSimulate);  // the models simulate takes
  cmd->add_option("--law", o->in.law, "FEM law with --method fem: linear, stvk, neohookean")->capture_default_str();
  cli::add_integrator_options(cmd, o->integrator, o->settings.simulator);
  cli::add_dynamics_options(cmd, o->settings.dynamics);
  cmd->add_option("--grab-radius", o->run.grab_radius, "Grab the surface nodes within this distance too, m")
      ->capture_default_str();
  cmd->add_option("--colormap", o->colormap,
                  "none, displacement, error, strain, weights, young (E per node: the tissues)")
      ->capture_default_str();
  cmd->add_option("--script", o->script, "Timed interactions to replay (docs/viewer.md)");
  cmd->add_option("--screenshot", o->run.screenshot, "Write the last frame as a PNG at exit");
  cmd->add_option("--frames", o->run.frames, "Exit after this many drawn frames (0: when the window closes)");
  cmd->add_option("--stats", o->run.stats, "Write the physics and draw rates and the probe force as JSON at exit");
  cmd->add_option("--save-model", o->run.save_model,
                  "Write the model being simulated at exit (.json, .vtu, .csv; what hooke calibrate writes)");
  cmd->add_option("--record", o->run.record, "Write the drawn frames as a ParaView series into this folder");
  cmd->add_option("--window-size", o->size, "Window size WIDTH,HEIGHT, pixels")->delimiter(',')->capture_default_str();
  cmd->add_flag("--no-panel", o->run.no_panel,
                "The scene alone: no panel, force arrow or colour bar (e.g. for pixel tests)");
  cmd->add_option("--threads", o->run.threads, "OpenMP threads of the physics thread")->capture_default_str();
  cmd->add_flag("--fast", o->fast, "Step as fast as possible instead of one step per dt of wall time");
  cmd->add_option(
         "--haptic-rate", o->run.haptic_rate,
         "Multirate haptics: a haptic loop at this rate (Hz, e.g. 1000) renders the probe force from the "
         "deformation's local model, which steps at --dt (at --qn-tolerance 1e-3 unless given); the mouse drives the "
         "haptic loop (0: off)")
      ->capture_default_str();
  cmd->add_flag("--haptic-curvature,!--no-haptic-curvature", o->settings.haptic_curvature,
                "The haptic local model's second-order term (the condensed energy's third derivative at the grab), "
                "or a model linear in the offset")
      ->capture_default_str();
  cmd->add_option("--haptic-stiffness", o->haptic_stiffness_name,
                  "The haptic local model's stiffness: secant (updated by every deformation step), condensed (the "
                  "rest stiffness condensed at the grab), none (the step's force held)")
      ->capture_default_str();
  return [o] { return run_view(*o); };
}

}  // namespace hooke::viewer
