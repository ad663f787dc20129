#include "reconfig/geometry/certain_plane.h"

#include <Eigen/Geometry>

#include <limits>

namespace reconfig::geometry {

CertainPlane certain_plane(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2) {
  constexpr double bound = 32 * std::numeric_limits<double>::epsilon();
  const Eigen::Vector3d e1 = p1 - p0, e2 = p2 - p0;
  CertainPlane plane;
  plane.origin = p0;
  plane.normal = e1.cross(e2);
  const double scale = plane.normal.squaredNorm() + e1.squaredNorm() * e2.squaredNorm();
  plane.error_factor = scale >= detail::kCertainPlaneTinySquare ? 2 * bound * bound * scale : std::numeric_limits<double>::infinity();
  return plane;
}

}  // namespace reconfig::geometry
