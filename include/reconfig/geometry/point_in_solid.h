#pragma once
/// @file
/// Inside/outside of a closed mesh.

#include <Eigen/Core>

#include "reconfig/geometry/mesh.h"

namespace reconfig::geometry {

/// Generalized winding number of `mesh` at `q` (Jacobson et al. 2013): 1 inside a closed,
/// outward-oriented mesh, 0 outside, fractional near holes. Slow reference: O(#F).
double winding_number(const Mesh& mesh, const Eigen::Vector3d& q);

/// Whether `q` lies strictly inside the solid bounded by the closed mesh (|winding| ≥ 0.5).
bool point_in_solid(const Mesh& mesh, const Eigen::Vector3d& q);

}  // namespace reconfig::geometry
