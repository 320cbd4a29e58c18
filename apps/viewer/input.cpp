#include "input.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace hooke::viewer {
namespace {
double g_scroll = 0.0;  // wheel steps since the last frame
}  // namespace

void MouseInput::install_scroll_callback(GLFWwindow* window) {
  glfwSetScrollCallback(window, [](GLFWwindow*, double, double dy) { g_scroll += dy; });
}

InputEvents MouseInput::poll(GLFWwindow* window, Camera& camera, const interactive::Snapshot& snap,
                             const interactive::SurfaceView& view, double grab_radius, int dim, double tool_radius) {
  InputEvents events;
  const ImGuiIO& io = ImGui::GetIO();
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window, &x, &y);
  int width = 1, height = 1, window_w = 1, window_h = 1;
  glfwGetFramebufferSize(window, &width, &height);
  glfwGetWindowSize(window, &window_w, &window_h);
  const double sx = static_cast<double>(width) / std::max(window_w, 1),
               sy = static_cast<double>(height) / std::max(window_h, 1);
  const bool left = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  const bool right = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  const bool middle = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
  const Ray ray = camera.ray(x * sx, y * sy, width, height);
  // The point where the ray meets the plane through `p` facing the camera (empty when the ray runs along it).
  const auto on_plane = [&](const Vec3& p) -> std::optional<Vec3> {
    const double denom = ray.direction.dot(m_plane_normal);
    if (std::abs(denom) <= 1e-9) return std::nullopt;
    return Vec3(ray.origin + (p - ray.origin).dot(m_plane_normal) / denom * ray.direction);
  };
  if (tool_radius > 0.0 && dim == 3) {  // press mode: the sphere touches the surface where clicked, from the camera
    if (left && !m_pressing && !io.WantCaptureMouse) {
      const RowMatX x3 = interactive::positions_3d(snap.positions, dim);
      if (const auto hit = interactive::pick_surface(x3, view.triangles, ray.origin, ray.direction)) {
        m_pressing = true;
        m_plane_normal = camera.forward();
        m_grab_point = hit->point - tool_radius * ray.direction.normalized();
        events.place_tool = m_grab_point;
      }
    } else if (left && m_pressing) {
      if (const auto p = on_plane(m_grab_point)) events.move_tool = *p;
    } else if (!left && m_pressing) {
      m_pressing = false;
      events.lift_tool = true;
    }
  } else if (left && !m_grabbing && !io.WantCaptureMouse) {
    const RowMatX x3 = interactive::positions_3d(snap.positions, dim);
    if (const auto hit = interactive::pick_surface(x3, view.triangles, ray.origin, ray.direction)) {
      events.grab = interactive::nodes_within(x3, view.nodes, hit->point, grab_radius, hit->nearest_node);
      m_grabbing = true;
      m_grab_point = x3.row(hit->nearest_node).transpose();
      m_plane_normal = camera.forward();
    }
  } else if (left && m_grabbing) {  // the probe moves on the plane through the grabbed point facing the camera
    if (const auto p = on_plane(m_grab_point)) events.drag = interactive::from_3d(*p - m_grab_point, dim);
  } else if (!left && m_grabbing) {
    m_grabbing = false;
    events.release = true;
  }
  const double dx = x - m_last_x, dy = y - m_last_y;
  if (right && !io.WantCaptureMouse) camera.orbit(dx, dy);
  if (middle && !io.WantCaptureMouse) camera.pan(dx * sx, dy * sy, height);
  if (g_scroll != 0.0 && !io.WantCaptureMouse) camera.zoom(g_scroll);
  g_scroll = 0.0;
  m_last_x = x;
  m_last_y = y;
  const bool space = glfwGetKey(window, GLFW_KEY_SPACE) == GLFW_PRESS, r = glfwGetKey(window, GLFW_KEY_R) == GLFW_PRESS,
             t = glfwGetKey(window, GLFW_KEY_T) == GLFW_PRESS;
  if (!io.WantCaptureKeyboard) {
    events.toggle_pause = space && !m_space_down;
    events.reset = r && !m_r_down;
    events.toggle_press = t && !m_t_down && !m_pressing && !m_grabbing;
  }
  m_space_down = space;
  m_r_down = r;
  m_t_down = t;
  return events;
}

}  // namespace hooke::viewer
