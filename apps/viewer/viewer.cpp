#include "viewer.hpp"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <chrono>
#include <hooke/calibrate/model_file.hpp>
#include <hooke/contact/tool_surface.hpp>
#include <hooke/core/error.hpp>
#include <hooke/interactive/fields.hpp>
#include <hooke/interactive/guarded.hpp>
#include <hooke/interactive/haptic_loop.hpp>
#include <hooke/interactive/physics_loop.hpp>
#include <hooke/interactive/picking.hpp>
#include <hooke/io/series.hpp>
#include <memory>
#include <thread>

#include "camera.hpp"
#include "colour_field.hpp"
#include "ghost.hpp"
#include "input.hpp"
#include "panel.hpp"
#include "renderer.hpp"
#include "stats.hpp"
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
          m_loop, [this](double) { return m_device.with([](const VecX& offset) { return offset; }); }, o.haptic_rate);
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
      ++m_draw.frames;
      ++frames_in_second;
      const Clock::time_point now = Clock::now();
      if (now - rate_start >= std::chrono::seconds(1)) {
        m_state.draw_rate = frames_in_second / std::chrono::duration<double>(now - rate_start).count();
        m_draw.timed_frames += frames_in_second;
        m_draw.seconds += std::chrono::duration<double>(now - rate_start).count();
        rate_start = now;
        frames_in_second = 0;
      }
      if (m_options.frames > 0 && m_draw.frames >= m_options.frames) break;
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
    if (!m_options.stats.empty())
      write_viewer_stats(m_options.stats, m_snap, m_state, m_draw, static_cast<int>(m_rest.size()) / m_dim, m_dim,
                         m_haptics != nullptr);
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

  // The mouse's and keys' events: to the physics, or the probe's offset to the haptic device.
  void handle_input() {
    const InputEvents e = m_input.poll(m_window, m_camera, m_snap, m_view, m_state.grab_radius, m_dim,
                                       m_state.press_mode ? tool_radius() : 0.0);
    if (e.toggle_press) m_state.press_mode = !m_state.press_mode;
    if (e.place_tool) {
      char shape[64];
      std::snprintf(shape, sizeof shape, "sphere:%.9g", tool_radius());
      m_loop.post([shape = std::string(shape), at = *e.place_tool,
                   mu = m_state.tool_friction](interactive::LiveSimulation& sim) {
        sim.set_tool(shape, {at, Mat3::Identity()}, mu);
      });
      m_tool_origin = *e.place_tool;
      if (m_haptics) set_device(VecX::Zero(3));  // the device now drives the tool from where it was put
    }
    if (e.move_tool) {
      if (m_haptics)  // the haptic loop moves it and renders its force from the local contact model
        set_device(*e.move_tool - m_tool_origin);
      else
        m_loop.post([at = *e.move_tool](interactive::LiveSimulation& sim) { sim.move_tool({at, Mat3::Identity()}); });
    }
    if (e.lift_tool) {
      m_loop.post([](interactive::LiveSimulation& sim) { sim.remove_tool(); });
      if (m_haptics) set_device(VecX());
    }
    if (e.grab) {
      m_loop.post([nodes = *e.grab](interactive::LiveSimulation& sim) { sim.grab(nodes); });
      set_device(VecX::Zero(m_dim));
    }
    if (e.drag) {
      if (m_haptics)
        set_device(*e.drag);
      else
        m_loop.post([offset = *e.drag](interactive::LiveSimulation& sim) { sim.drag(offset); });
    }
    if (e.release) {
      solve_ghost(false);  // the FEM under the displacement just let go of
      m_loop.post([](interactive::LiveSimulation& sim) { sim.release(); });
      set_device(VecX());
    }
    if (e.toggle_pause) toggle_pause();
    if (e.reset) m_loop.post([](interactive::LiveSimulation& sim) { sim.reset(); });
  }

  // The pressing sphere's radius, m: the panel's, or 5 % of the scene.
  double tool_radius() const { return m_state.tool_radius > 0.0 ? m_state.tool_radius : 0.05 * m_scene_size; }

  // The tool as the last snapshot has it, lit in grey (its triangles made again when its shape changes).
  void draw_tool(const Mat4f& view, const Mat4f& projection) {
    if (!m_snap.tool) return;
    const contact::ToolSurface surface = contact::tool_surface(m_snap.tool->tool, 48);
    const std::string shape = m_snap.tool->tool.description();
    if (!m_tool_renderer || shape != m_tool_shape) {
      m_tool_renderer = std::make_unique<Renderer>(surface.triangles, std::vector<std::array<int, 2>>{});
      m_tool_shape = shape;
    }
    m_tool_renderer->draw_surface(
        surface.nodes,
        std::vector<std::array<float, 3>>(static_cast<size_t>(surface.nodes.rows()), {0.62f, 0.64f, 0.68f}), view,
        projection);
  }

  void solve_ghost(bool now) { m_ghost.solve(m_loop, m_snap, m_state, now); }
  void poll_ghost() { m_ghost.poll(m_state); }

  // The haptic device's offset, m (empty: no mouse input, the script's drag or none).
  void set_device(const VecX& offset) {
    m_device.with([&](VecX& device) { device = offset; });
  }

  void toggle_pause() {
    m_state.paused = !m_loop.paused();
    m_loop.set_paused(m_state.paused);
    if (m_state.paused) solve_ghost(false);
  }

  void draw_frame() {
    glfwGetFramebufferSize(m_window, &m_width, &m_height);
    if (m_haptics) {
      m_state.haptic = m_haptics->stats();
      m_state.haptic_force = m_haptics->force();
    }
    // The force history: the last 5 s of simulated time.
    if ((m_snap.probe_force.size() > 0 || m_snap.tool) &&
        (m_state.force_history.empty() || m_state.force_history.back().first < m_snap.stats.sim_time)) {
      const double f = m_snap.tool ? m_snap.tool->force.norm() : m_snap.probe_force.norm();
      m_state.force_history.emplace_back(m_snap.stats.sim_time, static_cast<float>(f));
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
    m_renderer.draw_surface(interactive::positions_3d(m_snap.positions, m_dim),
                            m_colours.colours(m_loop, m_snap, m_rest, m_dim, m_state), view, projection);
    if (m_state.ghost != Ghost::kOff && m_state.ghost_positions)
      m_renderer.draw_wireframe(interactive::positions_3d(*m_state.ghost_positions, m_dim), {0.1f, 0.1f, 0.1f}, view,
                                projection);
    draw_tool(view, projection);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  }

  void record() {
    if (!m_series) return;
    m_series->write(m_snap.stats.sim_time, {{"displacement", m_dim, VecX(m_snap.positions - m_rest)}});
  }

  const ViewerOptions& m_options;
  GLFWwindow* m_window;
  int m_dim;
  interactive::SurfaceView m_view;
  Renderer m_renderer;
  interactive::PhysicsLoop m_loop;  // its thread calls nothing of the viewer's
  ViewState m_state;
  Camera m_camera;
  MouseInput m_input;
  interactive::Snapshot m_snap;
  VecX m_rest;
  double m_scene_size = 1.0;
  GhostSolver m_ghost;
  ColourField m_colours;
  std::unique_ptr<io::SeriesWriter> m_series;
  interactive::Guarded<VecX> m_device{VecX()};         // the mouse's offset for the haptic loop
  Vec3 m_tool_origin = Vec3::Zero();                   // where the mouse put the tool (the device's zero)
  std::unique_ptr<interactive::HapticLoop> m_haptics;  // last: stopped before what it reads goes
  int m_width = 1, m_height = 1;
  DrawCounts m_draw;
  std::unique_ptr<Renderer> m_tool_renderer;  // the tool's triangles, for m_tool_shape
  std::string m_tool_shape;
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
  MouseInput::install_scroll_callback(window.get());
  ImGuiSession imgui(window.get());  // after our scroll callback: ImGui chains to it
  Viewer viewer(o, window.get());
  return viewer.run();
}

}  // namespace hooke::viewer
