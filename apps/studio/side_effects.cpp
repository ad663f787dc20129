#include "side_effects.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace reconfig::studio {
namespace {

bool involves(const collision::CollisionInterval& ci, int part) {
  return std::find(ci.parts.begin(), ci.parts.end(), part) != ci.parts.end();
}

double time_gap(const collision::CollisionInterval& ci, double t) { return std::abs(t - std::clamp(t, ci.t0, ci.t1)); }

// Sorts before: appeared before changed; among appeared, longer first; among changed, growing
// before shrinking, then longer first.
bool more_critical(const collision::IntervalDiffEntry& a, const collision::IntervalDiffEntry& b) {
  using collision::IntervalChange;
  if (a.change != b.change) return a.change == IntervalChange::kAppeared;
  if (a.change == IntervalChange::kChanged && (a.growth > 0) != (b.growth > 0)) return a.growth > 0;
  return a.after->duration() > b.after->duration();
}

}  // namespace

int focused_interval(const std::vector<collision::CollisionInterval>& intervals, double t, int part) {
  const bool any_of_part = part >= 0 && std::any_of(intervals.begin(), intervals.end(),
                                                    [&](const auto& ci) { return involves(ci, part); });
  int best = -1;
  double best_gap = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < intervals.size(); ++i) {
    if (any_of_part && !involves(intervals[i], part)) continue;
    const double gap = time_gap(intervals[i], t);
    if (gap < best_gap) {
      best = static_cast<int>(i);
      best_gap = gap;
    }
  }
  return best;
}

bool same_collision(const collision::CollisionInterval& a, const collision::CollisionInterval& b) {
  return a.parts == b.parts && a.t0 <= b.t1 && b.t0 <= a.t1;
}

std::optional<collision::CollisionInterval> most_critical_side_effect(
    const std::vector<collision::IntervalDiffEntry>& changes,
    const std::optional<collision::CollisionInterval>& worked_on) {
  std::vector<collision::IntervalDiffEntry> effects;
  for (const collision::IntervalDiffEntry& entry : changes) {
    const bool side_effect = entry.change == collision::IntervalChange::kAppeared ||
                             entry.change == collision::IntervalChange::kChanged;
    if (side_effect && entry.after && !(worked_on && same_collision(*entry.after, *worked_on)))
      effects.push_back(entry);
  }
  if (effects.empty()) return std::nullopt;
  return *std::min_element(effects.begin(), effects.end(), more_critical)->after;
}

}  // namespace reconfig::studio
