#pragma once
/// @file
/// The nearest points of two triangles, and their distance: what the clearance check and the
/// proximity term measure between two parts.

#include <Eigen/Core>

#include "reconfig/geometry/triangle_corners.h"

namespace reconfig::geometry {

struct TriangleClosestPoints {
  double distance = 0;  ///< |on_a − on_b|; 0 where the closed triangles share a point
  Eigen::Vector3d on_a = Eigen::Vector3d::Zero();  ///< a nearest point of triangle a
  Eigen::Vector3d on_b = Eigen::Vector3d::Zero();  ///< and of triangle b
};

/// The nearest points of the closed triangles a and b. Where they share a point (decided
/// exactly, `triangles_intersect`) the distance is 0 and both points are the same
/// corner-or-edge point of the least of the 15 feature pairs below (near the contact, not
/// necessarily on it). Otherwise the nearest points are those of one of the 6 vertex–triangle
/// or 9 edge–edge pairs (true of two disjoint triangles), in floating point. Degenerate
/// triangles are the segments or points they collapse to.
TriangleClosestPoints triangle_closest_points(const TriangleCorners& a, const TriangleCorners& b);

/// The distance of `triangle_closest_points` (the same value), deciding first whether the
/// triangles share a point: cheaper where they often do.
double triangle_distance(const TriangleCorners& a, const TriangleCorners& b);

}  // namespace reconfig::geometry
