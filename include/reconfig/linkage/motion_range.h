#pragma once
/// @file
/// Where the motion of a linkage stops working: the motor angles at which a reconstruction
/// triangle flattens (degenerates) and then cannot close, so the crank only rocks.

#include <string>

#include "reconfig/linkage/symbolic_kinematics.h"

namespace reconfig::linkage {

/// The motor angles reachable from the initial configuration without a singularity.
struct MotionRange {
  bool full_rotation = false;  ///< the crank turns all the way round
  /// Unwrapped angles (radians), lower ≤ initial ≤ upper; for a full rotation
  /// [initial, initial + 2π].
  double lower = 0, upper = 0;
  /// What stops the motion just beyond each end (kind kNone for a full rotation); the
  /// message names the triangle that flattens there.
  ReconstructionFailure lower_failure, upper_failure;

  /// True if `angle` (radians, any winding) can be reached from the initial configuration.
  bool contains(double angle) const;
  /// "full rotation", or "rocks between 12.0° and 147.0° (at both ends: triangle …
  /// flattens (a dead point) and cannot close beyond)".
  std::string describe() const;
};

/// Scans the motor angle from the initial value in both directions in steps of `step`
/// radians, and refines each end by bisection to 1e-12 rad.
MotionRange motion_range(const SymbolicKinematics& kinematics, double step = 0.25 * 3.14159265358979323846 / 180);

}  // namespace reconfig::linkage
