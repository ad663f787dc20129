#pragma once
/// @file
/// Triangulating one planar-ish polygon of a mesh file (internal).

#include <Eigen/Core>
#include <vector>

namespace reconfig::geometry::detail {

/// Splits the polygon `loop` (indices into `positions`, in order) into triangles that keep its
/// orientation, by ear clipping in the plane of its Newell normal; concave polygons are
/// handled. Degenerate polygons (no normal, or no ear left) and very large ones (more than 1000
/// corners) are fanned from their first corner instead.
/// @param positions  #P positions
/// @param loop       n ≥ 3 indices into `positions`
/// @param triangles  receives n - 2 triangles (appended)
void triangulate_polygon(const std::vector<Eigen::Vector3d>& positions, const std::vector<int>& loop,
                         std::vector<Eigen::Vector3i>& triangles);

}  // namespace reconfig::geometry::detail
