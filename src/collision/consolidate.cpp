#include "reconfig/collision/consolidate.h"

#include <algorithm>

#include "collision/detail/interval_merging.h"

namespace reconfig::collision {
namespace {

/// Only intervals of the same pair of parts merge: each interval a designer sees names one pair
/// (the paper's collision intervals are per pair), and counts of intervals are counts per pair.
bool can_merge(const CollisionInterval& a, const CollisionInterval& b, double max_duration) {
  return a.parts == b.parts && a.clearance == b.clearance && detail::intervals_meet(a, b) &&
         std::max(a.t1, b.t1) - std::min(a.t0, b.t0) <= max_duration;
}

}  // namespace

CollisionInterval contact_interval(const TriangleContact& c) {
  return {c.t0, c.t1, {c.part_a, c.part_b}, c.box, false, c.possible, {{c.part_a, c.triangle_a, c.part_b, c.triangle_b}}};
}

std::vector<CollisionInterval> consolidate(const std::vector<TriangleContact>& contacts,
                                           const std::vector<Containment>& containments, double max_duration) {
  std::vector<CollisionInterval> items;
  items.reserve(contacts.size());
  for (const TriangleContact& c : contacts) items.push_back(contact_interval(c));
  return consolidate(std::move(items), containments, max_duration);
}

std::vector<CollisionInterval> consolidate(std::vector<CollisionInterval> items,
                                           const std::vector<Containment>& containments, double max_duration) {
  for (const Containment& c : containments)
    items.push_back({c.t0, c.t1, {std::min(c.inner, c.outer), std::max(c.inner, c.outer)}, c.box, true, false, {}});
  std::stable_sort(items.begin(), items.end(),
                   [](const CollisionInterval& a, const CollisionInterval& b) { return a.t0 < b.t0; });

  // Sweeps in time: each group joins the first earlier group still open that it can merge
  // with, or stays. Groups that grew may meet groups they did not meet before, so sweep again
  // until a sweep merges nothing: then no two groups can merge (every pair that meets in time
  // was compared). Each sweep is linear in the groups times the open ones; a few sweeps suffice.
  std::vector<CollisionInterval> groups = std::move(items);
  for (bool merged = true; merged;) {
    merged = false;
    std::vector<CollisionInterval> next;
    std::vector<std::size_t> open;  // indices into next that may still meet later groups
    for (CollisionInterval& group : groups) {
      std::erase_if(open, [&](std::size_t g) { return next[g].t1 + detail::kAdjacent < group.t0; });
      bool joined = false;
      for (const std::size_t g : open)
        if (can_merge(next[g], group, max_duration)) {
          detail::absorb(next[g], group);
          joined = merged = true;
          break;
        }
      if (!joined) {
        next.push_back(std::move(group));
        open.push_back(next.size() - 1);
      }
    }
    groups = std::move(next);
    std::stable_sort(groups.begin(), groups.end(),
                     [](const CollisionInterval& a, const CollisionInterval& b) { return a.t0 < b.t0; });
  }
  for (CollisionInterval& group : groups) {
    std::sort(group.triangles.begin(), group.triangles.end());
    group.triangles.erase(std::unique(group.triangles.begin(), group.triangles.end()), group.triangles.end());
  }
  std::sort(groups.begin(), groups.end(), [](const CollisionInterval& a, const CollisionInterval& b) {
    return std::tie(a.t0, a.parts, a.t1) < std::tie(b.t0, b.parts, b.t1);
  });
  return groups;
}

}  // namespace reconfig::collision
