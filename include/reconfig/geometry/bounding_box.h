#pragma once
/// @file
/// The axis-aligned box of a set of points.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace reconfig::geometry {

/// Smallest axis-aligned box containing every row of V (an empty box if V has no rows).
/// @param V  #V×3 points
inline Eigen::AlignedBox3d bounding_box(const Eigen::MatrixX3d& V) {
  if (V.rows() == 0) return {};
  return {V.colwise().minCoeff().transpose(), V.colwise().maxCoeff().transpose()};
}

}  // namespace reconfig::geometry
