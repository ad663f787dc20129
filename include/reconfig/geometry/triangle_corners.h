#pragma once
/// @file
/// A triangle as its three corners, in order.

#include <Eigen/Core>

#include <array>

namespace reconfig::geometry {

using TriangleCorners = std::array<Eigen::Vector3d, 3>;

}  // namespace reconfig::geometry
