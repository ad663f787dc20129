#pragma once
/// @file
/// A collision interval (CI): when, where and which parts collide (reconfigurables §3).

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace reconfig::collision {

/// Parts that interfere over a stretch of time of one transition.
struct CollisionInterval {
  double t0 = 0, t1 = 0;  ///< time extent within [0, 1] (t0 == t1 for a single instant)
  std::vector<int> parts;  ///< indices of the parts involved, ascending
  /// Spatial box of the intersection (segments where surfaces cross, or the contained
  /// part when one part lies entirely inside another) over the whole time extent.
  Eigen::AlignedBox3d box;
  /// True when the parts overlap without their surfaces crossing (one inside the other).
  bool containment = false;
};

/// All collision intervals of one transition, ordered by (t0, parts).
struct TransitionCollisions {
  int transition = 0;
  std::string name;
  std::vector<CollisionInterval> intervals;
};

}  // namespace reconfig::collision
