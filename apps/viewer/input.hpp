#pragma once
// The mouse and keyboard of the viewer's window: left-drag grabs and drives the surface as a probe (or, in press mode,
// puts a sphere on the surface where it is clicked and moves it on the plane facing the camera), right-drag /
// middle-drag / wheel move the camera, Space pauses, R resets and T switches between grabbing and pressing. What they
// ask of the physics comes back as events.
#include <hooke/interactive/fields.hpp>
#include <hooke/interactive/physics_loop.hpp>
#include <hooke/interactive/picking.hpp>
#include <optional>
#include <vector>

#include "camera.hpp"

struct GLFWwindow;

namespace hooke::viewer {

/// What the user did this frame that the physics (or the haptic device) must hear of.
struct InputEvents {
  std::optional<std::vector<int>> grab;  ///< the nodes just grabbed (model numbering)
  std::optional<VecX> drag;              ///< the probe's offset from where it grabbed, m (dim)
  bool release = false;                  ///< the probe let go
  std::optional<Vec3> place_tool;        ///< press mode: the tool's centre where it first touches, m
  std::optional<Vec3> move_tool;         ///< press mode: its centre as the mouse moves it, m
  bool lift_tool = false;                ///< press mode: the button let go, the tool lifted away
  bool toggle_press = false;             ///< T pressed
  bool toggle_pause = false;             ///< Space pressed
  bool reset = false;                    ///< R pressed
};

class MouseInput {
 public:
  /// Counts the wheel's steps for the camera; call once, before ImGui installs its callbacks (it chains to ours).
  static void install_scroll_callback(GLFWwindow* window);

  /// Reads the window's mouse and keys (not those ImGui takes), moves `camera`, picks on `snap`'s surface and
  /// returns the probe's and the keys' events.
  /// @param grab_radius  nodes within this distance of the picked point are grabbed too, m
  /// @param tool_radius  > 0: press mode with a sphere of this radius, m; 0: grab mode
  InputEvents poll(GLFWwindow* window, Camera& camera, const interactive::Snapshot& snap,
                   const interactive::SurfaceView& view, double grab_radius, int dim, double tool_radius = 0.0);

 private:
  bool m_grabbing = false;
  Eigen::Vector3d m_grab_point = Eigen::Vector3d::Zero(), m_plane_normal = Eigen::Vector3d::UnitZ();
  double m_last_x = 0.0, m_last_y = 0.0;
  bool m_pressing = false;
  bool m_space_down = false, m_r_down = false, m_t_down = false;
};

}  // namespace hooke::viewer
