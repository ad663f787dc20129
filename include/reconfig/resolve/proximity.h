#pragma once
/// @file
/// How much two placed parts lack of a reach c: the proximity term, which gives an energy and a
/// descent direction to near misses the collision detector reports as interference.
///
/// The detector decides interference on its proxies (`collision/spacetime_proxy.h`), which
/// stray up to its tolerance from the true motion, and its contact tests accept contacts within
/// a distance tolerance: an interval it reports may be one where the true surfaces only come
/// that close, or touch within the contact tolerance δ — with neither a contour nor a point
/// inside to measure. The deficit D = max(0, c − d), d the least distance between the parts'
/// surfaces (0 where they meet or overlap), is positive wherever they come closer than c and
/// falls as they move apart.

#include <Eigen/Geometry>

#include "reconfig/collision/spacetime_detector.h"
#include "reconfig/resolve/part_shape.h"
#include "reconfig/resolve/twist_gradient.h"

namespace reconfig::resolve {

struct Proximity {
  /// d: the least distance between the surfaces when it is below the reach, else the reach.
  double distance = 0;
  double deficit = 0;  ///< D = c − d (deficits below 1e-9 c are rounding of a gap of c: none)
  /// ∂D/∂(rigid motion of a), b held still: −n at a's nearest point, n the unit vector from
  /// b's nearest point to a's (moving a along n widens the gap); zero where d = 0.
  TwistGradient gradient;
  Eigen::Vector3d nearest_a = Eigen::Vector3d::Zero();  ///< world, when d < c
  Eigen::Vector3d nearest_b = Eigen::Vector3d::Zero();
};

/// The proximity of part a placed by `place_a` and part b by `place_b` (rest frame → world)
/// within the reach c > 0: the triangle pairs whose boxes come within c (the rest-frame trees,
/// `TriangleBvh::for_each_pair_within`), each pair's nearest points (exact intersection test,
/// floating-point distances). The caller that already knows the parts overlap (a contour or a
/// point inside) sets D = c itself.
Proximity proximity(const PartShape& a, const Eigen::Isometry3d& place_a, const PartShape& b,
                    const Eigen::Isometry3d& place_b, double reach);

/// The reach for intervals found by a detector with these options: twice its tolerance (each
/// of two moving parts' proxies strays up to the tolerance from its true motion, so the
/// detector may report interference where the true surfaces are that close).
double proximity_reach(const collision::DetectorOptions& detector);

}  // namespace reconfig::resolve
