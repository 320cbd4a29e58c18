#pragma once
// An orbit camera around a target, z up (the meshes' vertical axis): right-drag orbits, middle-drag pans, the wheel
// zooms; and the ray under a pixel, for picking.
#include <Eigen/Dense>

namespace hooke::viewer {

using Mat4f = Eigen::Matrix4f;

struct Ray {
  Eigen::Vector3d origin, direction;  ///< direction of unit length
};

class Camera {
 public:
  /// Frames the box [lo, hi] (m) from the front and a little above.
  void fit(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);
  void orbit(double dx_pixels, double dy_pixels);
  void pan(double dx_pixels, double dy_pixels, int height_pixels);
  void zoom(double wheel_steps);
  /// Moves the image right by `pixels` (the scene centred in what a panel on the left leaves free).
  void set_shift(double pixels) { m_shift = pixels; }

  Mat4f view() const;
  /// Perspective projection of a viewport `width` pixels wide with aspect width / height.
  Mat4f projection(int width, int height) const;
  Eigen::Vector3d eye() const;
  Eigen::Vector3d forward() const;  ///< unit, from the eye to the target
  /// The ray through pixel (x, y) (origin top left) of a width x height viewport.
  Ray ray(double x, double y, int width, int height) const;
  /// Pixel (origin top left) of point p; z > 1 or w <= 0 behind the camera (returns false).
  bool project(const Eigen::Vector3d& p, int width, int height, Eigen::Vector2d& pixel) const;

 private:
  Eigen::Vector3d m_target = Eigen::Vector3d::Zero();
  double m_distance = 1.0, m_yaw = -1.5707963267948966, m_pitch = 0.35, m_fov = 0.7853981633974483;
  double m_near = 1e-3, m_far = 1e3, m_shift = 0.0;
};

}  // namespace hooke::viewer
