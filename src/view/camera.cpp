#include "reconfig/view/camera.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace reconfig::view {

Eigen::Vector3d Camera::eye() const {
  const double c = std::cos(pitch);
  return target + distance * Eigen::Vector3d(c * std::cos(yaw), c * std::sin(yaw), std::sin(pitch));
}

Eigen::Vector3d Camera::forward() const { return (target - eye()).normalized(); }

Eigen::Vector3d Camera::right() const {
  // forward × z, computed from yaw so it stays defined when pitch is near ±π/2.
  return Eigen::Vector3d(-std::sin(yaw), std::cos(yaw), 0.0);
}

Eigen::Vector3d Camera::up() const { return right().cross(forward()).normalized(); }

Eigen::Matrix4d Camera::view_matrix() const {
  const Eigen::Vector3d f = forward(), r = right(), u = up(), e = eye();
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = r.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -r.dot(e);
  m(1, 3) = -u.dot(e);
  m(2, 3) = f.dot(e);
  return m;
}

Eigen::Matrix4d Camera::projection_matrix(double aspect) const {
  assert(aspect > 0 && near_plane > 0 && far_plane > near_plane);
  const double f = 1.0 / std::tan(fov_y / 2);
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = f / aspect;
  m(1, 1) = f;
  m(2, 2) = (far_plane + near_plane) / (near_plane - far_plane);
  m(2, 3) = 2 * far_plane * near_plane / (near_plane - far_plane);
  m(3, 2) = -1;
  return m;
}

double Camera::fov_x(double aspect) const { return 2 * std::atan(aspect * std::tan(fov_y / 2)); }

void Camera::orbit(double delta_yaw, double delta_pitch) {
  yaw = std::remainder(yaw + delta_yaw, 2 * M_PI);
  pitch = std::clamp(pitch + delta_pitch, -kMaxPitch, kMaxPitch);
}

void Camera::pan(double dx, double dy) { target += dx * right() + dy * up(); }

void Camera::zoom(double factor) {
  assert(factor > 0);
  distance *= factor;
  near_plane *= factor;
  far_plane *= factor;
}

void Camera::frame_all(const Eigen::AlignedBox3d& box, double aspect, double margin) {
  if (box.isEmpty()) return;
  pitch = std::clamp(pitch, -kMaxPitch, kMaxPitch);
  target = box.center();
  // Keep the direction, and find the smallest distance that puts every corner of the box (a
  // convex set: the corners suffice) inside the frustum scaled down by `margin`.
  const Eigen::Vector3d f = forward(), r = right(), u = up();
  const double tan_y = std::tan(fov_y / 2) / margin, tan_x = std::tan(fov_x(aspect) / 2) / margin;
  const double radius = std::max(0.5 * box.diagonal().norm(), 1e-6);
  double needed = 0;
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3d o = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)) - target;
    // A corner at depth distance + o·f is visible when |o·r| ≤ depth tan_x and |o·u| ≤ depth tan_y.
    needed = std::max({needed, std::abs(o.dot(r)) / tan_x - o.dot(f), std::abs(o.dot(u)) / tan_y - o.dot(f)});
  }
  distance = std::max(needed, 1.05 * radius);  // the eye stays outside the box's sphere
  fit_planes(box);
}

void Camera::fit_planes(const Eigen::AlignedBox3d& box) {
  if (box.isEmpty()) return;
  const double radius = std::max(0.5 * box.diagonal().norm(), 1e-6);
  const double reach = (eye() - box.center()).norm();  // the eye to the box's center
  near_plane = std::max(reach - radius, 0.0) * 0.5 + distance * 1e-3;
  far_plane = (reach + radius) * 20;  // room for the ground grid around the box
}

}  // namespace reconfig::view
