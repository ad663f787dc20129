#pragma once
/// @file
/// Exact-position vertex welding (internal to the geometry module).

#include <Eigen/Core>
#include <vector>

namespace reconfig::geometry::detail {

/// Merges vertices at bit-identical positions (+0 and -0 count as equal) and drops the
/// vertices no face uses. New vertices keep the order of `positions` (each at its first
/// occurrence).
/// @param positions  #P raw positions (finite)
/// @param faces      #F triangles indexing `positions` (in range)
/// @param V          #V×3 welded positions (output)
/// @param F          #F×3 triangles indexing `V`, same order as `faces` (output)
void weld_vertices(const std::vector<Eigen::Vector3d>& positions, const std::vector<Eigen::Vector3i>& faces,
                   Eigen::MatrixX3d& V, Eigen::MatrixX3i& F);

}  // namespace reconfig::geometry::detail
