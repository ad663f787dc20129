#pragma once
/// @file
/// One-shot spacetime collision detection over the transitions of a reconfigurable (the
/// request/result front door to `SpacetimeDetector`, FCL style).

#include <vector>

#include "reconfig/collision/collision_interval.h"
#include "reconfig/collision/spacetime_detector.h"

namespace reconfig::collision {

struct CollisionRequest {
  DetectorOptions detector;
  /// Transitions to check (indices); empty means all.
  std::vector<int> transitions;
  ProgressCallback progress;  ///< fraction over all transitions; false cancels
};

struct CollisionResult {
  /// Per checked transition: maximally consolidated intervals (the timeline's view).
  std::vector<TransitionCollisions> transitions;
  /// Per checked transition: intervals no longer than `frame` (the 3D view's boxes).
  std::vector<TransitionCollisions> frames;
  DetectionStats stats;  ///< summed over transitions
  bool cancelled = false;

  bool any_collision() const;
};

/// Detects every collision of every requested transition.
/// @throws InputError at `collision.tolerance` if the tolerance is too fine for the size of
///   the moving parts (tolerance_scale.h): refused at once rather than minutes of time steps
CollisionResult detect_collisions(const scene::Reconfigurable& scene, const CollisionRequest& request = {});

}  // namespace reconfig::collision
