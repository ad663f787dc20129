#include "reconfig/view/box_view_camera.h"

#include <algorithm>
#include <cmath>

namespace reconfig::view {

double box_view_distance(const Eigen::AlignedBox3d& box, double fov, double min_radius) {
  const double radius = std::max(box.isEmpty() ? 0.0 : 0.5 * box.diagonal().norm(), min_radius);
  return radius / std::sin(fov / 2);
}

Camera box_view_camera(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& direction, double aspect, double fov_y,
                       double min_radius) {
  Camera camera;
  camera.fov_y = fov_y;
  camera.target = box.isEmpty() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(box.center());
  const Eigen::Vector3d d = direction.normalized();
  camera.yaw = std::atan2(d.y(), d.x());
  camera.pitch = std::clamp(std::asin(std::clamp(d.z(), -1.0, 1.0)), -Camera::kMaxPitch, Camera::kMaxPitch);
  const double radius = std::max(box.isEmpty() ? 0.0 : 0.5 * box.diagonal().norm(), min_radius);
  camera.distance = box_view_distance(box, std::min(fov_y, camera.fov_x(aspect)), min_radius);
  camera.near_plane = camera.distance * 1e-3;
  camera.far_plane = camera.distance + 1.01 * radius;
  return camera;
}

}  // namespace reconfig::view
