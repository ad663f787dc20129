#pragma once
/// @file
/// A collision interval (CI): when, where and which parts collide (reconfigurables §3).

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
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
  /// Conservative detection only: every contact merged here is a near miss of the proxies
  /// that the true motion may turn into a collision (no confirmed intersection).
  bool possible = false;
  /// The triangle pairs involved (part a, triangle a, part b, triangle b): those the detector
  /// found — every one with `DetectorOptions::all_contacts`, else the witnesses that fixed the
  /// interval's extent; empty for the reference check and for pure containment.
  std::vector<std::array<int, 4>> triangles;
  /// A clearance interval (`DetectorOptions::clearance`, `check --clearance`): the parts come
  /// closer than the clearance but do not collide (parts that only touch come closer).
  bool clearance = false;

  double duration() const { return t1 - t0; }
};

/// All collision intervals of one transition, ordered by (t0, parts).
struct TransitionCollisions {
  int transition = 0;
  std::string name;
  std::vector<CollisionInterval> intervals;
};

}  // namespace reconfig::collision
