#include "viewer.hpp"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <chrono>
#include <hooke/calibrate/model_file.hpp>
#include <hooke/core/error.hpp>
#include <hooke/interactive/fields.hpp>
#include <hooke/interactive/haptic_loop.hpp>
#include <hooke/interactive/latest_job.hpp>
#include <hooke/interactive/physics_loop.hpp>
#include <hooke/interactive/picking.hpp>
#include <hooke/io/series.hpp>
#include <memory>
#include <mutex>
#include <thread>

#include "camera.hpp"
#include "panel.hpp"
#include "renderer.hpp"
#include "view_state.hpp"

namespace hooke::viewer {
namespace {

using Clock = std::chrono::steady_clock;
constexpr const char* kXvfbHint =
    "run it on a desktop, or headless under xvfb-run -a -s \"-screen 0 1024x768x24\" (package xvfb, installed by "
    "scripts/setup.sh)";

std::string g_glfw_error;  // the last GLFW error, for messages

struct GlfwSession {
  GlfwSession() {
    glfwSetErrorCallback([](int, const char* what) { g_glfw_error = what ? what : ""; });
    if (!glfwInit()) throw Error("cannot open a window: no display (" + g_glfw_error + "); " + kXvfbHint);
  }
  ~GlfwSession() { glfwTerminate(); }
};

struct ImGuiSession {
  explicit ImGuiSession(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini next to the user's files
    ImGui::StyleColorsLight();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
  }
  ~ImGuiSession() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
};

double g_scroll = 0.0;  // wheel steps since the last frame

// The mouse as a probe: where it grabbed, on which plane it drags.
struct MouseProbe {
  bool grabbing = false;
  Vec3 grab_point = Vec3::Zero(), plane_normal = Vec3::UnitZ();
  bool orbiting = false, panning = false;
  double last_x = 0.0, last_y = 0.0;
  bool space_down = false, r_down = false;
};

class Viewer {
 public:
  Viewer(const ViewerOptions& o, GLFWwindow* window)
      : m_options(o),
        m_window(window),
        m_dim(o.model.mesh.dim()),
        m_view(interactive::surface_view(o.model.mesh)),
        m_renderer(m_view.triangles, m_view.edges),
        m_loop(interactive::LiveSimulation(o.model, o.settings), o.realtime, o.threads) {
    m_state.field = interactive::color_field_from_name(o.colormap);
    m_state.grab_radius = o.grab_radius;
    m_loop.with([&](const interactive::LiveSimulation& sim) {
      m_state.edit = sim.settings();
      m_rest = sim.rest_positions();
    });
    const RowMatX rest = interactive::positions_3d(m_rest, m_dim);
    m_scene_size = (rest.colwise().maxCoeff() - rest.colwise().minCoeff()).norm();
    m_camera.fit(rest.colwise().minCoeff().transpose(), rest.colwise().maxCoeff().transpose());
    m_camera.set_shift(o.no_panel ? 0.0 : 0.5 * kPanelWidth);  // centred in what the panel leaves free
    if (!o.script.empty()) m_loop.set_script(o.script);
    if (!o.record.empty()) m_series = std::make_unique<io::SeriesWriter>(o.record, o.model.mesh);
    if (m_state.field == interactive::ColorField::kError) m_state.ghost = Ghost::kLinear;
    if (o.haptic_rate > 0.0)  // the mouse drives the haptic loop's device; the loop drives the deformation
      m_haptics = std::make_unique<interactive::HapticLoop>(
          m_loop,
          [this](double) {
            std::lock_guard lock(m_device_mutex);
            return m_device_offset;
          },
          o.haptic_rate);
  }

  int run() {
    m_loop.start();
    if (m_haptics) m_haptics->start();
    Clock::time_point next_frame = Clock::now(), rate_start = next_frame;
    int frames_in_second = 0;
    bool quit = false;
    while (!glfwWindowShouldClose(m_window) && !quit) {
      glfwPollEvents();
      // The script's drawing commands with the state of their time (the physics waits until drawing_done()).
      const std::vector<interactive::ScriptCommand> commands = m_loop.drawing_commands(m_snap);
      std::vector<std::string> screenshots;
      for (const interactive::ScriptCommand& c : commands) quit |= carry_out(c, screenshots);
      handle_input();
      poll_ghost();
      draw_frame();
      for (const std::string& file : screenshots)
        write_png(file, m_renderer.read_pixels(m_width, m_height), m_width, m_height);
      if (!commands.empty()) m_loop.drawing_done();
      record();
      glfwSwapBuffers(m_window);
      ++m_frames;
      ++frames_in_second;
      const Clock::time_point now = Clock::now();
      if (now - rate_start >= std::chrono::seconds(1)) {
        m_state.draw_rate = frames_in_second / std::chrono::duration<double>(now - rate_start).count();
        m_draw_rate_total += frames_in_second;
        m_draw_seconds += std::chrono::duration<double>(now - rate_start).count();
        rate_start = now;
        frames_in_second = 0;
      }
      if (m_options.frames > 0 && m_frames >= m_options.frames) break;
      // At most 60 frames per second: without a vertical sync (Xvfb) drawing would take a whole core from the
      // physics thread.
      next_frame += std::chrono::microseconds(16667);
      if (Clock::now() > next_frame) next_frame = Clock::now();
      std::this_thread::sleep_until(next_frame);
    }
    if (m_haptics) {
      m_haptics->stop();
      m_state.haptic = m_haptics->stats();
      m_state.haptic_force = m_haptics->force();
    }
    m_loop.stop();
    m_loop.snapshot(m_snap);
    if (!m_options.screenshot.empty()) {
      draw_frame();
      write_png(m_options.screenshot, m_renderer.read_pixels(m_width, m_height), m_width, m_height);
    }
    if (m_series) m_series->commit();
    if (!m_options.save_model.empty())
      m_loop.with(
          [&](const interactive::LiveSimulation& sim) { calibrate::write_model(m_options.save_model, sim.model()); });
    if (!m_options.stats.empty()) write_stats();
    return 0;
  }

 private:
  // A drawing command of the script; true for quit.
  bool carry_out(const interactive::ScriptCommand& c, std::vector<std::string>& screenshots) {
    switch (c.action) {
      case interactive::ScriptAction::kColormap:
        m_state.field = interactive::color_field_from_name(c.key);
        if (m_state.field == interactive::ColorField::kError && m_state.ghost == Ghost::kOff) {
          m_state.ghost = Ghost::kLinear;
          solve_ghost(true);
        }
        return false;
      case interactive::ScriptAction::kGhost:
        m_state.ghost = c.key == "off" ? Ghost::kOff : c.key == "linear" ? Ghost::kLinear : Ghost::kStVK;
        if (m_state.ghost != Ghost::kOff) solve_ghost(true);
        return false;
      case interactive::ScriptAction::kScreenshot: screenshots.push_back(c.key); return false;
      default: return true;  // quit
    }
  }

  // The FEM static solution under the probe's current displacement: now (scripted: the physics waits for it) or in
  // the background (interactive: the window stays live; poll_ghost picks it up).
  void solve_ghost(bool now) {
    if (m_state.ghost == Ghost::kOff) return;
    calibrate::CalibratedModel model;
    std::vector<int> clamped;
    bool gravity = false;
    m_loop.with([&](const interactive::LiveSimulation& sim) {
      model = sim.model();
      clamped = sim.clamped_nodes();
      gravity = sim.settings().dynamics.gravity;
    });
    const std::vector<int> grabbed = m_snap.grabbed;
    VecX targets = m_snap.grab_positions;
    for (size_t k = 0; k < grabbed.size(); ++k)
      targets.segment(m_dim * static_cast<Eigen::Index>(k), m_dim) += m_snap.probe_offset;
    const material::Law law = m_state.ghost == Ghost::kLinear ? material::Law::kLinear : material::Law::kStVK;
    auto job = [model = std::move(model), clamped, grabbed, targets, gravity, law] {
      return interactive::fem_probe_equilibrium(model, law, clamped, grabbed, targets, gravity);
    };
    m_state.ghost_message = "solving ...";
    if (now) {
      m_ghost.run_now(job);
    } else {
      m_ghost.submit(std::move(job));  // an older solve still running is left to finish: its result is dropped
    }
    poll_ghost();
  }

  void poll_ghost() {
    try {
      std::optional<interactive::ProbeEquilibrium> r = m_ghost.take();
      if (!r) return;
      m_state.ghost_positions = std::move(r->positions);
      m_state.ghost_force = std::move(r->holding_force);
      m_state.ghost_message = r->message;
    } catch (const std::exception& e) {
      m_state.ghost_positions.reset();
      m_state.ghost_force.resize(0);
      m_state.ghost_message = e.what();
    }
  }

  void handle_input() {
    ImGuiIO& io = ImGui::GetIO();
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(m_window, &x, &y);
    glfwGetFramebufferSize(m_window, &m_width, &m_height);
    int window_w = 1, window_h = 1;
    glfwGetWindowSize(m_window, &window_w, &window_h);
    const double sx = static_cast<double>(m_width) / std::max(window_w, 1),
                 sy = static_cast<double>(m_height) / std::max(window_h, 1);
    const bool left = glfwGetMouseButton(m_window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    const bool right = glfwGetMouseButton(m_window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
    const bool middle = glfwGetMouseButton(m_window, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
    const Ray ray = m_camera.ray(x * sx, y * sy, m_width, m_height);
    if (left && !m_mouse.grabbing && !io.WantCaptureMouse) {
      const RowMatX x3 = interactive::positions_3d(m_snap.positions, m_dim);
      if (const auto hit = interactive::pick_surface(x3, m_view.triangles, ray.origin, ray.direction)) {
        const std::vector<int> nodes =
            interactive::nodes_within(x3, m_view.nodes, hit->point, m_state.grab_radius, hit->nearest_node);
        m_mouse.grabbing = true;
        m_mouse.grab_point = x3.row(hit->nearest_node).transpose();
        m_mouse.plane_normal = m_camera.forward();
        m_loop.post([nodes](interactive::LiveSimulation& sim) { sim.grab(nodes); });
        set_device(VecX::Zero(m_dim));
      }
    } else if (left && m_mouse.grabbing) {
      const double denom = ray.direction.dot(m_mouse.plane_normal);
      if (std::abs(denom) > 1e-9) {
        const double s = (m_mouse.grab_point - ray.origin).dot(m_mouse.plane_normal) / denom;
        const VecX offset = interactive::from_3d(ray.origin + s * ray.direction - m_mouse.grab_point, m_dim);
        if (m_haptics)
          set_device(offset);
        else
          m_loop.post([offset](interactive::LiveSimulation& sim) { sim.drag(offset); });
      }
    } else if (!left && m_mouse.grabbing) {
      m_mouse.grabbing = false;
      solve_ghost(false);  // the FEM under the displacement just let go of
      m_loop.post([](interactive::LiveSimulation& sim) { sim.release(); });
      set_device(VecX());
    }
    const double dx = x - m_mouse.last_x, dy = y - m_mouse.last_y;
    if (right && !io.WantCaptureMouse) m_camera.orbit(dx, dy);
    if (middle && !io.WantCaptureMouse) m_camera.pan(dx * sx, dy * sy, m_height);
    if (g_scroll != 0.0 && !io.WantCaptureMouse) m_camera.zoom(g_scroll);
    g_scroll = 0.0;
    m_mouse.last_x = x;
    m_mouse.last_y = y;
    const bool space = glfwGetKey(m_window, GLFW_KEY_SPACE) == GLFW_PRESS,
               r = glfwGetKey(m_window, GLFW_KEY_R) == GLFW_PRESS;
    if (!io.WantCaptureKeyboard) {
      if (space && !m_mouse.space_down) toggle_pause();
      if (r && !m_mouse.r_down) m_loop.post([](interactive::LiveSimulation& sim) { sim.reset(); });
    }
    m_mouse.space_down = space;
    m_mouse.r_down = r;
  }

  // The haptic device's offset, m (empty: no mouse input, the script's drag or none).
  void set_device(const VecX& offset) {
    std::lock_guard lock(m_device_mutex);
    m_device_offset = offset;
  }

  void toggle_pause() {
    m_state.paused = !m_loop.paused();
    m_loop.set_paused(m_state.paused);
    if (m_state.paused) solve_ghost(false);
  }

  // Per-node colours of the current field, and the colour bar's range.
  std::vector<std::array<float, 3>> colours() {
    const int n = static_cast<int>(m_rest.size()) / m_dim;
    VecX value = VecX::Zero(n);
    double lo = 0.0, hi = 1.0;
    switch (m_state.field) {
      case interactive::ColorField::kNone: break;
      case interactive::ColorField::kDisplacement:
        value = interactive::displacement_magnitude(m_snap.positions, m_rest, m_dim);
        hi = value.maxCoeff();
        break;
      case interactive::ColorField::kError:
        // Up to the largest error, but at least 1 % of the largest displacement: where the model is the FEM the
        // map is uniform (the lowest colour), not its round-off stretched over the whole range.
        if (m_state.ghost_positions && m_state.ghost_positions->size() == m_snap.positions.size())
          value = interactive::node_distance(m_snap.positions, *m_state.ghost_positions, m_dim);
        hi = std::max(value.maxCoeff(),
                      0.01 * interactive::displacement_magnitude(m_snap.positions, m_rest, m_dim).maxCoeff());
        break;
      case interactive::ColorField::kStrain: {
        if (m_springs_version != m_snap.model_version) {  // the springs change only with the model
          m_loop.with([&](const interactive::LiveSimulation& sim) { m_springs = sim.model().springs; });
          m_springs_version = m_snap.model_version;
        }
        value = interactive::spring_strain(m_springs, m_snap.positions, n);
        hi = value.cwiseAbs().maxCoeff();
        lo = -hi;
        break;
      }
      case interactive::ColorField::kWeights: {
        // The blocks are shared and immutable: the weights are computed here, not under the physics' lock.
        if (m_built_version != m_snap.model_version) {
          m_loop.with([&](const interactive::LiveSimulation& sim) { m_built = sim.built_model(); });
          m_built_version = m_snap.model_version;
        }
        if (m_built.volume_penalty)
          value =
              m_built.volume_penalty->weights(m_snap.positions, m_snap.interaction ? &*m_snap.interaction : nullptr);
        else
          value.setOnes();
        lo = 0.0;
        hi = 1.0;
        break;
      }
    }
    if (!(hi > lo)) hi = lo + 1e-12;
    m_state.colour_lo = lo;
    m_state.colour_hi = hi;
    std::vector<std::array<float, 3>> out(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i)
      out[static_cast<size_t>(i)] = m_state.field == interactive::ColorField::kNone
                                        ? std::array<float, 3>{0.80f, 0.62f, 0.55f}
                                        : interactive::colormap((value(i) - lo) / (hi - lo));
    return out;
  }

  void draw_frame() {
    glfwGetFramebufferSize(m_window, &m_width, &m_height);
    if (m_haptics) {
      m_state.haptic = m_haptics->stats();
      m_state.haptic_force = m_haptics->force();
    }
    // The force history: the last 5 s of simulated time.
    if (m_snap.probe_force.size() > 0 &&
        (m_state.force_history.empty() || m_state.force_history.back().first < m_snap.stats.sim_time)) {
      m_state.force_history.emplace_back(m_snap.stats.sim_time, static_cast<float>(m_snap.probe_force.norm()));
      while (m_state.force_history.front().first < m_snap.stats.sim_time - 5.0) m_state.force_history.pop_front();
    }
    if (!ImGui::IsAnyItemActive()) {  // the panel follows the physics (a script may change settings)
      const double radius = m_state.grab_radius;
      m_state.edit = m_snap.settings;
      m_state.grab_radius = radius;
    }
    m_state.paused = m_snap.stats.paused;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    const PanelRequests r =
        m_options.no_panel ? PanelRequests{} : draw_panel(m_state, m_snap, static_cast<int>(m_rest.size()) / m_dim);
    if (r.apply_settings) {
      const interactive::LiveSettings s = m_state.edit;
      m_loop.post([s](interactive::LiveSimulation& sim) { sim.apply(s); });
    }
    if (r.reset) m_loop.post([](interactive::LiveSimulation& sim) { sim.reset(); });
    if (r.toggle_pause) toggle_pause();
    if (r.solve_ghost) solve_ghost(false);
    if (!m_options.no_panel) draw_overlays(m_state, m_snap, m_camera, m_width, m_height, m_dim, m_scene_size);
    ImGui::Render();

    m_renderer.clear(m_width, m_height);
    const Mat4f view = m_camera.view(), projection = m_camera.projection(m_width, m_height);
    m_renderer.draw_surface(interactive::positions_3d(m_snap.positions, m_dim), colours(), view, projection);
    if (m_state.ghost != Ghost::kOff && m_state.ghost_positions)
      m_renderer.draw_wireframe(interactive::positions_3d(*m_state.ghost_positions, m_dim), {0.1f, 0.1f, 0.1f}, view,
                                projection);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  }

  void record() {
    if (!m_series) return;
    m_series->write(m_snap.stats.sim_time, {{"displacement", m_dim, VecX(m_snap.positions - m_rest)}});
  }

  void write_stats() {
    const VecX f = m_snap.probe_force.size() > 0 ? m_snap.probe_force : VecX::Zero(m_dim);
    std::vector<std::pair<std::string, double>> extra{
        {"draw_rate_hz", m_draw_seconds > 0.0 ? m_draw_rate_total / m_draw_seconds : m_state.draw_rate},
        {"frames", m_frames},
        {"nodes", static_cast<double>(m_rest.size() / m_dim)},
        {"grabbed_nodes", static_cast<double>(m_snap.grabbed.size())},
        {"probe_force_n", f.norm()},
        {"young_pa", m_snap.settings.material.youngs_modulus},
        {"poisson", m_snap.settings.material.poisson_ratio},
        {"dt_s", m_snap.settings.dynamics.dt}};
    for (int a = 0; a < m_dim; ++a) extra.emplace_back(std::string("probe_force_") + "xyz"[a], f(a));
    if (m_state.ghost_force.size() == m_dim) extra.emplace_back("fem_holding_force_n", m_state.ghost_force.norm());
    if (m_haptics) {
      const interactive::HapticStats& h = m_state.haptic;
      extra.insert(extra.end(),
                   {{"haptic_target_rate_hz", h.target_rate},
                    {"haptic_rate_hz", h.achieved_rate},
                    {"haptic_period_ms_median", h.period_ms_median},
                    {"haptic_period_ms_p99", h.period_ms_p99},
                    {"haptic_tick_ms_p99", h.tick_ms_p99},
                    {"haptic_ticks", static_cast<double>(h.ticks)},
                    {"deformation_models_per_s", h.model_rate},
                    {"haptic_force_n", m_state.haptic_force.size() > 0 ? m_state.haptic_force.norm() : 0.0}});
    }
    interactive::write_stats(m_options.stats, m_snap.stats, extra);
  }

  const ViewerOptions& m_options;
  GLFWwindow* m_window;
  int m_dim;
  interactive::SurfaceView m_view;
  Renderer m_renderer;
  interactive::PhysicsLoop m_loop;  // its thread calls nothing of the viewer's
  ViewState m_state;
  Camera m_camera;
  MouseProbe m_mouse;
  interactive::Snapshot m_snap;
  VecX m_rest;
  double m_scene_size = 1.0;
  interactive::LatestJob<interactive::ProbeEquilibrium> m_ghost;
  std::unique_ptr<io::SeriesWriter> m_series;
  calibrate::SpringModel m_springs;
  long m_springs_version = -1;
  calibrate::BuiltModel m_built;  // the model's blocks, for the Eq. 4 weights
  long m_built_version = -1;
  std::mutex m_device_mutex;  // the mouse's offset for the haptic loop
  VecX m_device_offset;
  std::unique_ptr<interactive::HapticLoop> m_haptics;  // last: stopped before what it reads goes
  int m_width = 1, m_height = 1, m_frames = 0;
  double m_draw_rate_total = 0.0, m_draw_seconds = 0.0;
};

}  // namespace

int run_viewer(const ViewerOptions& o) {
  GlfwSession glfw;
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  std::unique_ptr<GLFWwindow, void (*)(GLFWwindow*)> window(
      glfwCreateWindow(o.width, o.height, ("hooke view: " + o.model.mesh.source).c_str(), nullptr, nullptr),
      glfwDestroyWindow);
  if (!window) throw Error("no OpenGL 3.3 core context (" + g_glfw_error + "); " + kXvfbHint);
  glfwMakeContextCurrent(window.get());
  glfwSwapInterval(1);
  glfwSetScrollCallback(window.get(), [](GLFWwindow*, double, double dy) { g_scroll += dy; });
  ImGuiSession imgui(window.get());  // after our scroll callback: ImGui chains to it
  Viewer viewer(o, window.get());
  return viewer.run();
}

}  // namespace hooke::viewer
