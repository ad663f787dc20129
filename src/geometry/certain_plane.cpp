#include "reconfig/geometry/certain_plane.h"

#include <Eigen/Geometry>

#include <limits>

namespace reconfig::geometry {

namespace {

/// Below this, squared lengths and their products are too close to underflow for the relative
/// error bound: such tests do not answer.
constexpr double kTinySquare = 1e-200;

}  // namespace

CertainPlane certain_plane(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2) {
  constexpr double bound = 32 * std::numeric_limits<double>::epsilon();
  const Eigen::Vector3d e1 = p1 - p0, e2 = p2 - p0;
  CertainPlane plane;
  plane.origin = p0;
  plane.normal = e1.cross(e2);
  const double scale = plane.normal.squaredNorm() + e1.squaredNorm() * e2.squaredNorm();
  plane.error_factor = scale >= kTinySquare ? 2 * bound * bound * scale : std::numeric_limits<double>::infinity();
  return plane;
}

int certain_side(const CertainPlane& plane, const Eigen::Vector3d& q) {
  const Eigen::Vector3d d = q - plane.origin;
  if (!(d.squaredNorm() >= kTinySquare)) return 0;
  const double s = plane.normal.dot(d);
  if (!(s * s > plane.error_factor * d.squaredNorm())) return 0;  // too close to tell (or NaN)
  return s > 0 ? 1 : -1;
}

KnownSides certain_sides(const CertainPlane& plane, const std::array<Eigen::Vector3d, 3>& triangle) {
  return {certain_side(plane, triangle[0]), certain_side(plane, triangle[1]), certain_side(plane, triangle[2])};
}

}  // namespace reconfig::geometry
