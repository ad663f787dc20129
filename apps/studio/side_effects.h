#pragma once
/// @file
/// Which collision interval the designer should look at: the one being worked on (under the
/// current time, of the selected part), and the most critical side effect of an edit
/// (reconfigurables §4.4) — appeared before changed, longer before shorter, growing before
/// shrinking — that is not the one being worked on.

#include <optional>
#include <vector>

#include "reconfig/collision/interval_diff.h"

namespace reconfig::studio {

/// The index of the interval being worked on: among those of `part` (any part when −1 or when
/// none is of `part`), the one containing time t, else the one nearest to t; −1 when empty.
int focused_interval(const std::vector<collision::CollisionInterval>& intervals, double t, int part);

/// Whether two intervals are the same collision: the same parts, overlapping (or touching) in time.
bool same_collision(const collision::CollisionInterval& a, const collision::CollisionInterval& b);

/// The interval (as it is after the edit) of the most critical appeared or changed entry of
/// `changes` that is not `worked_on`; none when there is no such side effect.
std::optional<collision::CollisionInterval> most_critical_side_effect(
    const std::vector<collision::IntervalDiffEntry>& changes,
    const std::optional<collision::CollisionInterval>& worked_on);

}  // namespace reconfig::studio
