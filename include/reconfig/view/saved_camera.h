#pragma once
/// @file
/// Between the orbit camera and the view a scene file keeps (scene::SavedView, in degrees).

#include <Eigen/Geometry>

#include "reconfig/scene/saved_view.h"
#include "reconfig/view/camera.h"

namespace reconfig::view {

/// The camera's target, distance, yaw and pitch, to be saved with the design.
scene::SavedView saved_view(const Camera& camera);

/// A camera placed as `saved` says, with its near and far planes around `scene_box` (the
/// part of the design it shows; Camera::fit_planes).
Camera camera_from(const scene::SavedView& saved, const Eigen::AlignedBox3d& scene_box);

}  // namespace reconfig::view
