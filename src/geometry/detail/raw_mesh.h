#pragma once
/// @file
/// What our own file readers produce before welding (internal).

#include <Eigen/Core>
#include <vector>

namespace reconfig::geometry::detail {

/// Positions and triangles as read from a file.
struct RawMesh {
  std::vector<Eigen::Vector3d> positions;  ///< the vertices, in file order
  std::vector<Eigen::Vector3i> triangles;  ///< polygons split into triangles, indices in range
};

}  // namespace reconfig::geometry::detail
