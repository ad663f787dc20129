#include "reconfig/collision/interval_diff.h"

#include <algorithm>
#include <cmath>

namespace reconfig::collision {
namespace {

double overlap(const CollisionInterval& a, const CollisionInterval& b) {
  return std::min(a.t1, b.t1) - std::max(a.t0, b.t0);
}

int rank(IntervalChange change) { return static_cast<int>(change); }

}  // namespace

std::vector<IntervalDiffEntry> diff_intervals(const std::vector<CollisionInterval>& before,
                                              const std::vector<CollisionInterval>& after, double epsilon) {
  std::vector<bool> used(before.size(), false);
  std::vector<IntervalDiffEntry> entries;
  for (const CollisionInterval& now : after) {
    int best = -1;
    double best_overlap = -1;
    for (std::size_t i = 0; i < before.size(); ++i) {
      if (used[i] || before[i].parts != now.parts) continue;
      const double o = overlap(before[i], now);
      if (o >= 0 && o > best_overlap) {
        best = static_cast<int>(i);
        best_overlap = o;
      }
    }
    IntervalDiffEntry entry;
    entry.after = now;
    if (best < 0) {
      entry.change = IntervalChange::kAppeared;
    } else {
      used[best] = true;
      entry.before = before[best];
      const bool same = std::abs(before[best].t0 - now.t0) <= epsilon && std::abs(before[best].t1 - now.t1) <= epsilon;
      entry.change = same ? IntervalChange::kUnchanged : IntervalChange::kChanged;
      entry.growth = same ? 0 : now.duration() - before[best].duration();
    }
    entries.push_back(std::move(entry));
  }
  for (std::size_t i = 0; i < before.size(); ++i)
    if (!used[i]) entries.push_back({IntervalChange::kDisappeared, before[i], std::nullopt, 0});

  const auto duration = [](const IntervalDiffEntry& e) { return (e.after ? e.after : e.before)->duration(); };
  const auto start = [](const IntervalDiffEntry& e) { return (e.after ? e.after : e.before)->t0; };
  std::stable_sort(entries.begin(), entries.end(), [&](const IntervalDiffEntry& a, const IntervalDiffEntry& b) {
    if (a.change != b.change) return rank(a.change) < rank(b.change);
    if (a.change == IntervalChange::kUnchanged) return start(a) < start(b);
    if (a.change == IntervalChange::kChanged && (a.growth > 0) != (b.growth > 0)) return a.growth > 0;
    return duration(a) > duration(b);
  });
  return entries;
}

}  // namespace reconfig::collision
