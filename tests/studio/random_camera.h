#pragma once
/// @file
/// Random viewpoints for the viewport math's oracle tests.

#include <random>

#include "reconfig/view/camera.h"

namespace reconfig::studio {

/// A camera looking at a target within the unit cube, from 1–5 units away, from any side and
/// somewhat above.
inline view::Camera random_camera(std::mt19937& random) {
  std::uniform_real_distribution<double> u(-1, 1);
  view::Camera camera;
  camera.target = Eigen::Vector3d(u(random), u(random), u(random));
  camera.distance = 3 + 2 * u(random);
  camera.yaw = 3 * u(random);
  camera.pitch = 0.2 + 0.5 * u(random);
  return camera;
}

}  // namespace reconfig::studio
