#pragma once
/// @file
/// Bounding boxes of a posed scene, for framing the camera.

#include <Eigen/Geometry>

#include "reconfig/scene/reconfigurable.h"

namespace reconfig::view {

/// Box of every part posed at time t of transition `transition`.
Eigen::AlignedBox3d scene_bounds_at(const scene::Reconfigurable& scene, int transition, double t);

/// Box of every part posed in state `state`.
Eigen::AlignedBox3d scene_bounds_in_state(const scene::Reconfigurable& scene, int state);

/// Box of every part over a whole transition, from `samples` (≥ 2) evenly spaced times.
Eigen::AlignedBox3d scene_bounds_over(const scene::Reconfigurable& scene, int transition, int samples = 11);

}  // namespace reconfig::view
