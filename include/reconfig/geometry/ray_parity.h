#pragma once
/// @file
/// Inside or outside a closed mesh by the parity of a ray's crossings, decided with
/// floating-point tests whose error bounds make them certain where they answer: much cheaper
/// than a nearest-point query for a point far from the surface, and silent (`kUnsure`) where
/// the ray grazes an edge or a vertex, or the point lies on a face's plane within rounding.

#include <Eigen/Core>

#include "reconfig/geometry/triangle_bvh.h"

namespace reconfig::geometry {

enum class RayParity {
  kEven,    ///< the ray crosses the mesh an even number of times: outside a closed mesh
  kOdd,     ///< an odd number of times: inside
  kUnsure,  ///< a crossing could not be decided for certain (ask a nearest-point query)
};

/// The parity of the triangles of `tree` that the ray from q along the axis-aligned direction
/// that leaves the tree's box soonest crosses. Each crossing is exact: q's projection lies
/// strictly inside the triangle's projection across the ray (three 2D orientations, Shewchuk's
/// error bound) and q lies certainly on the near side of the triangle's plane
/// (`certain_plane.h`). For a closed mesh (every edge shared by exactly two faces) kEven means
/// q lies outside the solid, kOdd inside, in the winding-number sense; q outside the tree's box
/// is kEven at once. Coordinates must be finite.
RayParity axis_ray_parity(const TriangleBvh& tree, const Eigen::Vector3d& q);

/// The 2D orientation of (a, b, c) projected on coordinates (i, j): +1 counterclockwise, −1
/// clockwise, 0 when the floating-point determinant cannot certify its sign (collinear, or
/// within the rounding bound).
int certain_orientation_2d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, int i, int j);

}  // namespace reconfig::geometry
