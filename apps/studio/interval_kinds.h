#pragma once
/// @file
/// Counting a transition's intervals by kind: collisions (red in the studio) and clearance
/// intervals (amber: closer than the clearance without colliding, docs/file-formats.md).

#include <algorithm>
#include <cstddef>
#include <vector>

#include "reconfig/collision/collision_interval.h"

namespace reconfig::studio {

/// How many of `intervals` are clearance intervals.
inline std::size_t clearance_count(const std::vector<collision::CollisionInterval>& intervals) {
  return static_cast<std::size_t>(std::count_if(intervals.begin(), intervals.end(),
                                                [](const collision::CollisionInterval& ci) { return ci.clearance; }));
}

}  // namespace reconfig::studio
