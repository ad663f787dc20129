#pragma once
/// @file
/// The winding number of a closed mesh at a point, counted along one axis-aligned ray whose
/// crossings are decided by floating-point tests that are certain where they answer: much
/// cheaper than a nearest-point query for a point far from the surface, and silent (not
/// `certain`) where the ray grazes an edge or a corner, or the point lies on a face's plane
/// within rounding.

#include <Eigen/Core>

#include "reconfig/geometry/triangle_bvh.h"

namespace reconfig::geometry {

struct RayWinding {
  /// Every crossing was decided; false: the count means nothing (ask a nearest-point query).
  bool certain = false;
  /// Σ ±1 over the triangles the ray crosses: +1 where the triangle's normal (by its corners'
  /// order, right-handed) points along the ray, −1 against it. For a closed, consistently
  /// oriented mesh (every edge shared by two faces that run it in opposite directions) this is
  /// the winding number at q: 0 outside, 1 inside an outward shell, 2 where two shells overlap
  /// or nest, −1 inside an inward one.
  int winding = 0;
};

/// The crossings of the ray from q along the axis-aligned direction that leaves the tree's box
/// soonest. Each is exact: q's projection lies strictly inside the triangle's projection across
/// the ray (three 2D orientations, Shewchuk's error bound) and q lies certainly on the near side
/// of the triangle's plane (`certain_plane.h`). q outside the tree's box: certain, 0 at once.
/// Coordinates must be finite.
RayWinding axis_ray_winding(const TriangleBvh& tree, const Eigen::Vector3d& q);

/// The 2D orientation of (a, b, c) projected on coordinates (i, j): +1 counterclockwise, −1
/// clockwise, 0 when the floating-point determinant cannot certify its sign (collinear, or
/// within the rounding bound).
int certain_orientation_2d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, int i, int j);

}  // namespace reconfig::geometry
