#pragma once
/// @file
/// Exact collinearity of three points (internal; keeps CGAL out of the callers).

#include <Eigen/Core>

namespace reconfig::geometry::detail {

/// Whether a, b, c lie on one line (or coincide), decided exactly on the double inputs.
/// @pre all coordinates finite
bool exactly_collinear(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace reconfig::geometry::detail
