#pragma once
/// @file
/// Ways to make target trajectories for trajectory editing (LinkEdit §4.1): transform a
/// whole motion curve, or drag one of its points with a soft selection.

#include <Eigen/Core>
#include <vector>

namespace reconfig::linkage {

/// The curve scaled by `scale` and rotated by `rotation` (radians, counterclockwise) about
/// its centroid, then translated by `translation`.
/// @param curve #S points
std::vector<Eigen::Vector2d> transform_curve(const std::vector<Eigen::Vector2d>& curve, double scale, double rotation,
                                             const Eigen::Vector2d& translation);

/// Soft-selection drag: point `index` moves by `displacement`, every other point by
/// displacement · exp(−(s / radius)²), s its arc-length distance to the dragged point along
/// the curve (the shorter way round when `closed`).
/// @param curve #S points
std::vector<Eigen::Vector2d> soft_drag_curve(const std::vector<Eigen::Vector2d>& curve, int index,
                                             const Eigen::Vector2d& displacement, double radius, bool closed);

}  // namespace reconfig::linkage
