// The sculpt tool's rotation rings (tool_rings.h).

#include "tool_rings.h"

#include <algorithm>
#include <cmath>

#include "gizmo.h"
#include "reconfig/view/picking.h"

namespace reconfig::studio {
ToolRings ToolRings::around(const view::Camera& camera, int height, const Eigen::Vector3d& center,
                            const Eigen::Matrix3d& axes, double reach) {
  return {center, axes, std::max(Gizmo::sized_for(camera, height, center).ring_radius, 1.1 * reach)};
}

std::vector<Eigen::Vector3d> ToolRings::ring(int axis, int segments) const {
  // The ring about axis a lies in the plane of the two other axes.
  const Eigen::Vector3d u = axes.col((axis + 1) % 3), v = axes.col((axis + 2) % 3);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i <= segments; ++i) {
    const double a = 2 * M_PI * i / segments;
    points.push_back(center + radius * (std::cos(a) * u + std::sin(a) * v));
  }
  return points;
}

bool ToolRings::edge_on(const view::Camera& camera, int axis) const {
  constexpr double kLeastCosine = 0.2;  // |cos| of the angle between the axis and the line of sight
  return std::abs(axes.col(axis).dot((center - camera.eye()).normalized())) < kLeastCosine;
}

std::optional<int> ToolRings::hit(const view::Camera& camera, int width, int height, const Eigen::Vector2d& mouse,
                                  double tolerance) const {
  std::optional<int> best;
  double best_distance = tolerance;
  for (int axis = 0; axis < 3; ++axis) {
    if (edge_on(camera, axis)) continue;
    const double distance = pixel_distance_to_polyline(camera, width, height, ring(axis), mouse);
    if (distance < best_distance) {
      best_distance = distance;
      best = axis;
    }
  }
  return best;
}

double swept_turn(const Eigen::Vector2d& center, const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                  const Eigen::Vector3d& axis, const Eigen::Vector3d& forward) {
  const Eigen::Vector2d a = from - center, b = to - center;
  if (a.squaredNorm() == 0 || b.squaredNorm() == 0) return 0;
  // Pixels run y down: a positive atan2 sweep is clockwise on screen, which is a positive turn
  // about an axis pointing away from the viewer.
  const double sweep = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
  return axis.dot(forward) >= 0 ? sweep : -sweep;
}

}  // namespace reconfig::studio
