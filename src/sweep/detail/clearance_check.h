#pragma once
/// @file
/// The a-posteriori check that makes a tight contour of the swept distance conservative: no
/// point of the mesh lies within a threshold of the sweep.

#include <Eigen/Geometry>

#include <functional>
#include <optional>

#include "reconfig/geometry/mesh.h"

namespace reconfig::sweep::detail {

/// x ↦ a lower bound of d(x, S), the distance from world point x to a closed set S.
using DistanceLowerBound = std::function<double(const Eigen::Vector3d& x)>;

/// Whether every point of every triangle of `mesh` that may meet `region` (all of them when
/// there is none) lies farther than `threshold` from S. Per triangle with corners v_i and
/// lower bounds L_i <= d(v_i, S): d² − |x|² is concave (a minimum of affine functions of x),
/// so at q = Σ λ_i v_i, d²(q) >= Σ λ_i L_i² − Σ λ_i |v_i − q|², a convex quadratic in λ whose
/// minimum over the triangle is found exactly (its stationary point or its edges). A triangle
/// that fails is split into four at its edges' midpoints (with lower bounds there), up to
/// `max_depth` times, before the check fails.
/// @param mesh         #V×3, #F×3
/// @param region       the box that matters, or none
/// @param threshold    >= 0
/// @param lower_bound  d(·, S) from below
bool mesh_keeps_clear(const geometry::Mesh& mesh, const std::optional<Eigen::AlignedBox3d>& region, double threshold,
                      const DistanceLowerBound& lower_bound, int max_depth = 2);

/// min over the triangle (v_0, v_1, v_2) of Σ λ_i L2_i − Σ λ_i |v_i − q|², q = Σ λ_i v_i.
/// @param v   the corners
/// @param L2  the squared lower bounds at the corners
double squared_distance_lower_bound(const Eigen::Vector3d v[3], const double L2[3]);

}  // namespace reconfig::sweep::detail
