#pragma once
/// @file
/// The camera that looks at a box from a direction, keeping all of it in view whatever the
/// direction (reconfigurables §4.3: the distance is chosen once for every candidate view).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "reconfig/view/camera.h"

namespace reconfig::view {

/// The smallest distance from the center of `box` at which its bounding sphere (radius at
/// least `min_radius`) lies wholly inside a view cone of full angle `fov` (radians).
double box_view_distance(const Eigen::AlignedBox3d& box, double fov, double min_radius = 0);

/// An orbit camera (up +z) aimed at the center of `box` from `direction` (from the box towards
/// the eye, any length > 0) at `box_view_distance(box, min(fov_y, fov_x), min_radius)` for a
/// viewport of that aspect. Near plane at a thousandth of the distance, far plane just behind
/// the box. Pitch is clamped to ±Camera::kMaxPitch, so straight down is 1.2° off.
Camera box_view_camera(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& direction, double aspect = 1,
                       double fov_y = Camera{}.fov_y, double min_radius = 0);

}  // namespace reconfig::view
