#pragma once
/// @file
/// The orbit camera: a target point, a distance, yaw and pitch around a fixed up axis (+z).

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace reconfig::view {

/// An orbit camera looking at `target` from `distance` away. The eye sits at
///   target + distance · (cos(pitch) cos(yaw), cos(pitch) sin(yaw), sin(pitch)),
/// so yaw turns the eye around the up axis +z (yaw = 0: eye on +x) and pitch lifts it
/// above the xy plane (pitch = π/2: looking straight down). Angles in radians.
/// Matrices follow the OpenGL conventions: right-handed eye space looking down −z, clip
/// space depth in [−1, 1], column vectors (clip = P · V · world).
struct Camera {
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  double distance = 3.0;
  double yaw = -1.0;   ///< radians
  double pitch = 0.45; ///< radians, kept within ±kMaxPitch
  double fov_y = 0.7;  ///< vertical field of view, radians
  double near_plane = 0.01;
  double far_plane = 100.0;

  /// Pitch is clamped to this (just short of ±π/2) so that the up axis never aligns with
  /// the viewing direction.
  static constexpr double kMaxPitch = 1.55;

  /// Eye position in world coordinates.
  Eigen::Vector3d eye() const;
  /// Unit vector from the eye towards the target.
  Eigen::Vector3d forward() const;
  /// Unit vector pointing right on screen (forward × z, normalized).
  Eigen::Vector3d right() const;
  /// Unit vector pointing up on screen (right × forward).
  Eigen::Vector3d up() const;

  /// World → eye transform (4×4, rigid).
  Eigen::Matrix4d view_matrix() const;
  /// Eye → clip perspective projection for a viewport of the given width / height.
  Eigen::Matrix4d projection_matrix(double aspect) const;

  /// Horizontal field of view for the aspect ratio width / height.
  double fov_x(double aspect) const;

  /// Turns the camera around the target (radians); pitch is clamped.
  void orbit(double delta_yaw, double delta_pitch);
  /// Moves the target in the screen plane by (dx, dy) world units (right, up).
  void pan(double dx, double dy);
  /// Multiplies the distance by `factor` (> 0); near and far planes follow.
  void zoom(double factor);

  /// Keeps yaw, pitch and fov, aims at the center of `box` and chooses the smallest distance
  /// at which all of the box is visible in a viewport of that aspect ratio, with `margin`
  /// (≥ 1) extra room, and the eye outside the box's bounding sphere. Sets near and far
  /// planes around the box. An empty box leaves the camera unchanged.
  void frame_all(const Eigen::AlignedBox3d& box, double aspect, double margin = 1.1);
  /// Keeps the eye where it is and sets the near and far planes so that all of `box` lies
  /// between them, with room behind it for the ground grid. An empty box leaves them unchanged.
  void fit_planes(const Eigen::AlignedBox3d& box);
};

}  // namespace reconfig::view
