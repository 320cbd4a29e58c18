#include "camera.hpp"

#include <algorithm>
#include <cmath>

namespace hooke::viewer {

void Camera::fit(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  m_target = 0.5 * (lo + hi);
  const double radius = std::max(0.5 * (hi - lo).norm(), 1e-9);
  m_distance = 1.4 * radius / std::sin(0.5 * m_fov);
  m_near = 1e-3 * m_distance;
  m_far = 1e3 * m_distance;
}

void Camera::orbit(double dx, double dy) {
  m_yaw -= 0.01 * dx;
  m_pitch = std::clamp(m_pitch + 0.01 * dy, -1.55, 1.55);
}

void Camera::pan(double dx, double dy, int height) {
  const Eigen::Vector3d f = forward(), right = f.cross(Eigen::Vector3d::UnitZ()).normalized(), up = right.cross(f);
  const double metres_per_pixel = 2.0 * m_distance * std::tan(0.5 * m_fov) / std::max(height, 1);
  m_target += metres_per_pixel * (-dx * right + dy * up);
}

void Camera::zoom(double steps) {
  m_distance *= std::pow(0.9, steps);
  m_near = 1e-3 * m_distance;
  m_far = 1e3 * m_distance;
}

Eigen::Vector3d Camera::eye() const {
  return m_target + m_distance * Eigen::Vector3d(std::cos(m_pitch) * std::cos(m_yaw),
                                                 std::cos(m_pitch) * std::sin(m_yaw), std::sin(m_pitch));
}

Eigen::Vector3d Camera::forward() const { return (m_target - eye()).normalized(); }

Mat4f Camera::view() const {
  const Eigen::Vector3d f = forward(), s = f.cross(Eigen::Vector3d::UnitZ()).normalized(), u = s.cross(f), e = eye();
  Mat4f v = Mat4f::Identity();
  v.block<1, 3>(0, 0) = s.cast<float>().transpose();
  v.block<1, 3>(1, 0) = u.cast<float>().transpose();
  v.block<1, 3>(2, 0) = -f.cast<float>().transpose();
  v(0, 3) = static_cast<float>(-s.dot(e));
  v(1, 3) = static_cast<float>(-u.dot(e));
  v(2, 3) = static_cast<float>(f.dot(e));
  return v;
}

Mat4f Camera::projection(int width, int height) const {
  const double aspect = static_cast<double>(width) / std::max(height, 1), t = 1.0 / std::tan(0.5 * m_fov);
  Mat4f p = Mat4f::Zero();
  p(0, 2) = static_cast<float>(-2.0 * m_shift / std::max(width, 1));  // x_ndc += shift after the divide by w = -z
  p(0, 0) = static_cast<float>(t / aspect);
  p(1, 1) = static_cast<float>(t);
  p(2, 2) = static_cast<float>(-(m_far + m_near) / (m_far - m_near));
  p(2, 3) = static_cast<float>(-2.0 * m_far * m_near / (m_far - m_near));
  p(3, 2) = -1.0f;
  return p;
}

Ray Camera::ray(double x, double y, int width, int height) const {
  const double aspect = static_cast<double>(width) / std::max(height, 1), t = std::tan(0.5 * m_fov);
  const double nx = (2.0 * (x - m_shift) / width - 1.0) * t * aspect, ny = (1.0 - 2.0 * y / height) * t;
  const Eigen::Vector3d f = forward(), s = f.cross(Eigen::Vector3d::UnitZ()).normalized(), u = s.cross(f);
  return Ray{eye(), (f + nx * s + ny * u).normalized()};
}

bool Camera::project(const Eigen::Vector3d& p, int width, int height, Eigen::Vector2d& pixel) const {
  const Eigen::Vector4f c =
      projection(width, height) * view() *
      Eigen::Vector4f(static_cast<float>(p(0)), static_cast<float>(p(1)), static_cast<float>(p(2)), 1.0f);
  if (c(3) <= 0.0f) return false;
  pixel = Eigen::Vector2d((c(0) / c(3) * 0.5 + 0.5) * width, (0.5 - c(1) / c(3) * 0.5) * height);
  return true;
}

}  // namespace hooke::viewer
