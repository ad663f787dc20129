#pragma once
/// @file
/// The first view of a design: from its working side, the side its moving parts move toward.
/// A kitchen against a wall is seen from the room, where its drawers slide out, not from
/// behind the wall.

#include <Eigen/Core>

#include "reconfig/scene/reconfigurable.h"
#include "reconfig/view/camera.h"

namespace reconfig::view {

/// The summed horizontal (xy) displacement of the parts' centers: over the first transition,
/// from t = 0 to eight evenly spaced times (so that a part that moves out and back still
/// counts); a design without transitions sums each state against the first one instead.
/// Zero when nothing moves sideways.
Eigen::Vector2d working_direction(const scene::Reconfigurable& scene);

/// Turns `camera` (keeping its target and distance) to a three-quarter view of the working
/// side: the yaw of the working direction less 30° (so that the front is seen with some
/// depth, from its right), 25° above the horizon. Without a working direction, the yaw is 60°
/// (from +x +y). Frame afterwards (Camera::frame_all); the first transition's collisions lie
/// in the frame of its motion, so the view needs no collision detection.
void aim_at_working_side(Camera& camera, const scene::Reconfigurable& scene);

}  // namespace reconfig::view
