#pragma once
/// @file
/// What changed between two sets of collision intervals, in the order a designer should hear
/// about it (reconfigurables §4.4: new before changed; longer before shorter; growing before
/// shrinking).

#include <optional>
#include <vector>

#include "reconfig/collision/collision_interval.h"

namespace reconfig::collision {

enum class IntervalChange { kAppeared, kChanged, kDisappeared, kUnchanged };

struct IntervalDiffEntry {
  IntervalChange change = IntervalChange::kUnchanged;
  std::optional<CollisionInterval> before;  ///< absent for kAppeared
  std::optional<CollisionInterval> after;   ///< absent for kDisappeared
  /// after.duration() − before.duration() (0 unless kChanged): > 0 grew, < 0 shrank.
  double growth = 0;
};

/// Matches each interval of `after` with the interval of `before` that involves the same parts
/// and overlaps it in time (the longest overlap wins; each matched at most once). Matched
/// intervals with the same extent (within `epsilon` in time) are unchanged, the rest changed;
/// unmatched ones appeared or disappeared.
/// @return entries ordered appeared (longest first), changed (growing before shrinking, then
///         longest first), disappeared (longest first), unchanged (by time)
std::vector<IntervalDiffEntry> diff_intervals(const std::vector<CollisionInterval>& before,
                                              const std::vector<CollisionInterval>& after, double epsilon = 1e-9);

}  // namespace reconfig::collision
