#pragma once
/// @file
/// A triangle's plane prepared for a floating-point side test that is certain where it answers:
/// the cheap filter in front of exact triangle–triangle tests.

#include <Eigen/Core>

#include <array>

#include "reconfig/geometry/triangle_intersection.h"

namespace reconfig::geometry {

/// The plane through p0, p1, p2 as the side test computes it: s(q) = n·(q − p0) with
/// n = (p1 − p0) × (p2 − p0), and the factor c of its error bound. The computed s(q) is within
/// sqrt(c)·|q − p0| of the exact orientation determinant orient(p0, p1, p2, q), for
/// c = 2 (32 ε)² (|n|² + |p1 − p0|² |p2 − p0|²) — twice the bound the exact triangle test
/// (`triangle_intersection.h`) uses for its own crossings. The bound is relative, so a test
/// where squared lengths fall below 1e-200 (edges or distances under 1e-100, where rounding
/// would underflow) does not answer.
struct CertainPlane {
  Eigen::Vector3d origin;   ///< p0
  Eigen::Vector3d normal;   ///< n, not normalized
  double error_factor;      ///< c (no initializers: arrays of planes are filled lazily)
};

/// The plane of the triangle (p0, p1, p2); a degenerate triangle gives a plane whose tests
/// never answer.
CertainPlane certain_plane(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2);

namespace detail {
/// Below this, squared lengths and their products are too close to underflow for the relative
/// error bound: such tests do not answer.
inline constexpr double kCertainPlaneTinySquare = 1e-200;
}  // namespace detail

// The side tests are inline: the contour filter calls them millions of times a second.

/// Whether q lies certainly strictly on the positive (+1) or negative (−1) side of the plane:
/// then the exact orientation has that sign. 0 when the test cannot tell (within its error
/// bound, on the plane, or NaN).
inline int certain_side(const CertainPlane& plane, const Eigen::Vector3d& q) {
  const Eigen::Vector3d d = q - plane.origin;
  if (!(d.squaredNorm() >= detail::kCertainPlaneTinySquare)) return 0;
  const double s = plane.normal.dot(d);
  if (!(s * s > plane.error_factor * d.squaredNorm())) return 0;  // too close to tell (or NaN)
  return s > 0 ? 1 : -1;
}

/// The certain sides of a triangle's corners (`certain_side` of each): what
/// `intersect_triangles` can take as known sides.
inline KnownSides certain_sides(const CertainPlane& plane, const std::array<Eigen::Vector3d, 3>& triangle) {
  return {certain_side(plane, triangle[0]), certain_side(plane, triangle[1]), certain_side(plane, triangle[2])};
}

/// Whether the sides put all three corners strictly on one side: then the triangle cannot
/// meet the plane's triangle.
inline bool all_on_one_side(const KnownSides& side) { return side[0] != 0 && side[0] == side[1] && side[1] == side[2]; }

}  // namespace reconfig::geometry
