#pragma once
/// @file
/// The sculpt tool's rotation rings (sculpt mode, sculpt_panel.h): three rings round the
/// tool's center about the tool's own x, y and z axes, which ring a screen point is on, and
/// the turn a drag round the center sweeps on screen. Pure math (no GL, no ImGui), tested
/// directly.

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "reconfig/view/camera.h"

namespace reconfig::studio {

struct ToolRings {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  ///< the tool's center (world)
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  ///< the tool's unit x, y, z axes (world), as columns
  double radius = 1;                                 ///< world units

  /// Rings round `center` about `axes`, as big on screen as the part gizmo's rings
  /// (gizmo.h) or, for a bigger tool, `reach` (world) plus a tenth.
  static ToolRings around(const view::Camera& camera, int height, const Eigen::Vector3d& center,
                          const Eigen::Matrix3d& axes, double reach);

  /// Ring `axis` (0 x, 1 y, 2 z) as a closed polyline in the world (`segments` + 1 points).
  std::vector<Eigen::Vector3d> ring(int axis, int segments = 64) const;

  /// Whether ring `axis` is seen nearly edge-on from `camera` (its axis less than about 12°
  /// from square to the line of sight to the center): drawn as a thin ellipse through the
  /// center, where a drag round the center is ill-defined, it is not picked.
  bool edge_on(const view::Camera& camera, int axis) const;

  /// The ring under the pixel `mouse` (viewport pixels, y down): the nearest one, not seen
  /// edge-on, whose projected polyline passes within `tolerance` pixels, or nothing.
  std::optional<int> hit(const view::Camera& camera, int width, int height, const Eigen::Vector2d& mouse,
                         double tolerance = 7) const;
};

/// The turn (radians, right-handed about `axis`) of a drag from pixel `from` to pixel `to`
/// round the pixel `center` (y down): the angle swept round the center on screen, positive
/// when it is counter-clockwise as seen with `axis` pointing at the viewer (`forward` is the
/// camera's viewing direction; a ring seen edge-on turns as if its axis pointed away). Zero
/// when either point is on the center.
double swept_turn(const Eigen::Vector2d& center, const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                  const Eigen::Vector3d& axis, const Eigen::Vector3d& forward);

}  // namespace reconfig::studio
