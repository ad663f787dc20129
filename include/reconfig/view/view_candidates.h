#pragma once
/// @file
/// Which directions to look at a collision from (reconfigurables §4.3): orthogonal to the
/// motions of two colliding parts, else many random directions on the (northern hemi)sphere.
/// Directions point from the collision towards the eye; all of them are unit vectors.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "reconfig/scene/reconfigurable.h"

namespace reconfig::view {

/// r = A(t1) − A(t0): how far the center of mass of part `part` moves between times t0 and t1
/// of transition `transition`.
/// @param scene a validated reconfigurable; transition and part valid indices
Eigen::Vector3d part_displacement(const scene::Reconfigurable& scene, int transition, int part, double t0, double t1);

/// ±(rA × rB) normalized: the two directions that see both motions in the view plane; none
/// when that is degenerate: a motion shorter than `min_ratio` times the other (a part that
/// holds still), or an angle between them whose sine is below `min_sine` (parallel motions).
std::optional<std::array<Eigen::Vector3d, 2>> motion_normal_directions(const Eigen::Vector3d& rA,
                                                                       const Eigen::Vector3d& rB,
                                                                       double min_sine = 0.02,
                                                                       double min_ratio = 1e-3);

/// `count` directions uniformly distributed on the unit sphere, or on its northern half
/// (z ≥ 0) when `northern_hemisphere` (a design standing on a ground: Shao & Badler, uniform
/// z and azimuth). The same seed gives the same directions.
std::vector<Eigen::Vector3d> random_view_directions(int count, bool northern_hemisphere, std::uint64_t seed);

/// ±x, ±y, +z and, unless `northern_hemisphere`, −z.
std::vector<Eigen::Vector3d> axis_view_directions(bool northern_hemisphere);

}  // namespace reconfig::view
