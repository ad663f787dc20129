#include "reconfig/view/saved_camera.h"

#include <algorithm>
#include <cmath>

namespace reconfig::view {
namespace {

constexpr double kDegree = M_PI / 180;

}  // namespace

scene::SavedView saved_view(const Camera& camera) {
  return {.target = camera.target,
          .distance = camera.distance,
          .yaw_degrees = camera.yaw / kDegree,
          .pitch_degrees = camera.pitch / kDegree};
}

Camera camera_from(const scene::SavedView& saved, const Eigen::AlignedBox3d& scene_box) {
  Camera camera;
  camera.target = saved.target;
  camera.distance = saved.distance;
  camera.yaw = saved.yaw_degrees * kDegree;
  camera.pitch = std::clamp(saved.pitch_degrees * kDegree, -Camera::kMaxPitch, Camera::kMaxPitch);
  camera.fit_planes(scene_box);
  return camera;
}

}  // namespace reconfig::view
