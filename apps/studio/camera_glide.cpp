#include "camera_glide.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace reconfig::studio {

view::Camera CameraGlide::at(double seconds) const {
  const double s = duration > 0 ? std::clamp((seconds - start) / duration, 0.0, 1.0) : 1.0;
  const double w = s * s * (3 - 2 * s);
  view::Camera camera = to;
  camera.target = from.target + w * (to.target - from.target);
  camera.distance = from.distance * std::pow(to.distance / from.distance, w);  // zooms at an even pace
  const double turn = std::remainder(to.yaw - from.yaw, 2 * std::numbers::pi);
  camera.yaw = std::remainder(from.yaw + w * turn, 2 * std::numbers::pi);
  camera.pitch = from.pitch + w * (to.pitch - from.pitch);
  return camera;
}

}  // namespace reconfig::studio
