#pragma once
/// @file
/// The move/rotate gizmo's math: where its handles are on screen, which one the mouse is
/// over, and the pose a drag produces. Pure math (no GL, no ImGui), so it is tested directly.

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "reconfig/motion/pose.h"
#include "reconfig/view/camera.h"
#include "reconfig/view/picking.h"

namespace reconfig::studio {

/// Arrows move along a world axis; rings rotate about one (through the gizmo's center).
enum class GizmoHandle { kNone, kMoveX, kMoveY, kMoveZ, kRotateX, kRotateY, kRotateZ };

bool is_rotation(GizmoHandle handle);
/// The world axis of a handle (unit x, y or z); zero for kNone.
Eigen::Vector3d handle_axis(GizmoHandle handle);

/// The gizmo in the world: centered on the selected part's pivot, sized so it keeps the same
/// size on screen at any zoom.
struct Gizmo {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double arrow_length = 1;  ///< world units
  double ring_radius = 0.8; ///< world units

  /// A gizmo whose arrows are `pixels` long on screen at `center` (viewport `height` pixels).
  static Gizmo sized_for(const view::Camera& camera, int height, const Eigen::Vector3d& center, double pixels = 90);

  /// The handle's shape in world coordinates: the arrow's segment (2 points) or the ring's
  /// closed polyline (`segments` + 1 points).
  std::vector<Eigen::Vector3d> shape(GizmoHandle handle, int segments = 64) const;

  /// The handle under the pixel `mouse` (within `tolerance` pixels of its projected shape),
  /// the nearest one when several are; arrows win over rings at equal distance.
  GizmoHandle hit(const view::Camera& camera, int width, int height, const Eigen::Vector2d& mouse,
                  double tolerance = 7) const;
};

/// A drag in progress: the handle, the gizmo center, the part's pose when it started and the
/// mouse ray then.
struct GizmoDrag {
  GizmoHandle handle = GizmoHandle::kNone;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  motion::Pose start_pose;
  view::Ray start_ray;

  /// The pose the part takes with the mouse ray now at `ray`: an arrow translates the part by
  /// how far the closest point of the axis line to the ray moved; a ring rotates it about the
  /// axis through `center` by the angle the ray's hit on the ring plane turned. A ray that
  /// runs (nearly) parallel to the axis or the plane keeps the start pose.
  motion::Pose pose_for(const view::Ray& ray) const;
};

/// How far, in pixels, `mouse` is from the drawn polyline `points` (projected segment by
/// segment; segments with an end behind the camera are skipped); infinity if none is drawn.
double pixel_distance_to_polyline(const view::Camera& camera, int width, int height,
                                  const std::vector<Eigen::Vector3d>& points, const Eigen::Vector2d& mouse);

/// Parameter s of the point center + s·axis of the axis line closest to the ray, or nullopt
/// when the two are (nearly) parallel.
std::optional<double> closest_axis_parameter(const view::Ray& ray, const Eigen::Vector3d& center,
                                             const Eigen::Vector3d& axis);
/// Signed angle (radians, right-handed about `axis`) of the point where the ray meets the
/// plane through `center` normal to `axis`, measured from `reference` (a vector in that
/// plane); nullopt when the ray misses the plane.
std::optional<double> ring_angle(const view::Ray& ray, const Eigen::Vector3d& center, const Eigen::Vector3d& axis,
                                 const Eigen::Vector3d& reference);

}  // namespace reconfig::studio
