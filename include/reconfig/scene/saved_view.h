#pragma once
/// @file
/// The camera a design was last looked at with, saved with it (the scene file's optional
/// "view" object), so that it opens the way it was left. Plain numbers: the view module turns
/// them into an orbit camera (view/saved_camera.h).

#include <Eigen/Core>

namespace reconfig::scene {

/// An orbit camera: the eye sits `distance` from `target`, turned `yaw_degrees` about +z from
/// +x and lifted `pitch_degrees` above the xy plane (view::Camera's conventions, in degrees).
struct SavedView {
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  double distance = 1;       ///< > 0, scene units
  double yaw_degrees = 0;    ///< any finite angle
  double pitch_degrees = 0;  ///< strictly within ±90

  bool operator==(const SavedView&) const = default;
};

}  // namespace reconfig::scene
