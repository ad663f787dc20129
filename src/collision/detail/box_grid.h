#pragma once
/// @file
/// Boxes rounded outward to a grid: the detector reports where contacts lie to a chosen
/// resolution, so that it can skip every contact that cannot change the rounded answer.

#include <Eigen/Geometry>
#include <cmath>

namespace reconfig::collision::detail {

/// `box` grown to the smallest box whose faces lie on the planes x = k·cell (k an integer,
/// likewise y and z) that contains it; `box` itself if `cell` is 0 or the box is empty.
/// Every rounded coordinate is computed as k·cell from its integer k, so equal grid planes
/// are equal doubles and rounding a rounded box changes nothing.
inline Eigen::AlignedBox3d round_out(const Eigen::AlignedBox3d& box, double cell) {
  if (!(cell > 0) || box.isEmpty()) return box;
  Eigen::AlignedBox3d rounded;
  for (int axis = 0; axis < 3; ++axis) {
    double below = std::floor(box.min()[axis] / cell), above = std::ceil(box.max()[axis] / cell);
    if (below * cell > box.min()[axis]) below -= 1;
    if (above * cell < box.max()[axis]) above += 1;
    rounded.min()[axis] = below * cell;
    rounded.max()[axis] = above * cell;
  }
  return rounded;
}

}  // namespace reconfig::collision::detail
