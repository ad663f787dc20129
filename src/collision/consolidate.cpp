#include "reconfig/collision/consolidate.h"

#include <algorithm>

namespace reconfig::collision {
namespace {

constexpr double kAdjacent = 1e-12;  ///< time gap under which two extents count as touching

void add_part(std::vector<int>& parts, int part) {
  const auto at = std::lower_bound(parts.begin(), parts.end(), part);
  if (at == parts.end() || *at != part) parts.insert(at, part);
}

bool boxes_meet(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b) {
  return (a.min().array() <= b.max().array()).all() && (b.min().array() <= a.max().array()).all();
}

bool times_meet(const CollisionInterval& a, const CollisionInterval& b) {
  return a.t0 <= b.t1 + kAdjacent && b.t0 <= a.t1 + kAdjacent;
}

void absorb(CollisionInterval& into, const CollisionInterval& other) {
  into.t0 = std::min(into.t0, other.t0);
  into.t1 = std::max(into.t1, other.t1);
  into.box.extend(other.box);
  for (int p : other.parts) add_part(into.parts, p);
  into.containment = into.containment || other.containment;
  into.possible = into.possible && other.possible;
  into.triangles.insert(into.triangles.end(), other.triangles.begin(), other.triangles.end());
}

bool can_merge(const CollisionInterval& a, const CollisionInterval& b, double max_duration) {
  return times_meet(a, b) && boxes_meet(a.box, b.box) &&
         std::max(a.t1, b.t1) - std::min(a.t0, b.t0) <= max_duration;
}

}  // namespace

std::vector<CollisionInterval> consolidate(const std::vector<TriangleContact>& contacts,
                                           const std::vector<Containment>& containments, double max_duration) {
  std::vector<CollisionInterval> items;
  items.reserve(contacts.size() + containments.size());
  for (const TriangleContact& c : contacts)
    items.push_back({c.t0, c.t1, {c.part_a, c.part_b}, c.box, false, c.possible,
                     {{c.part_a, c.triangle_a, c.part_b, c.triangle_b}}});
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
      std::erase_if(open, [&](std::size_t g) { return next[g].t1 + kAdjacent < group.t0; });
      bool joined = false;
      for (const std::size_t g : open)
        if (can_merge(next[g], group, max_duration)) {
          absorb(next[g], group);
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
