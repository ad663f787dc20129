#include "collision/detail/contact_hints.h"

#include <array>
#include <tuple>

namespace reconfig::collision::detail {

std::vector<ContactHint> extreme_contacts(const std::vector<TriangleContact>& contacts, const FrameGrid& grid) {
  // Per pair of parts and frame: the contact with the lowest box minimum and the highest box
  // maximum along each axis, the earliest start and the latest end.
  constexpr int kExtremes = 8;
  std::map<std::tuple<int, int, int>, std::array<const TriangleContact*, kExtremes>> extremes;
  for (const TriangleContact& c : contacts) {
    if (c.possible) continue;
    auto& best = extremes.try_emplace({c.part_a, c.part_b, frame_of_contact(grid, c)}).first->second;
    const auto keep = [&](int k, auto further) {
      if (!best[k] || further(*best[k])) best[k] = &c;
    };
    for (int axis = 0; axis < 3; ++axis) {
      keep(axis, [&](const TriangleContact& b) { return c.box.min()[axis] < b.box.min()[axis]; });
      keep(3 + axis, [&](const TriangleContact& b) { return c.box.max()[axis] > b.box.max()[axis]; });
    }
    keep(6, [&](const TriangleContact& b) { return c.t0 < b.t0; });
    keep(7, [&](const TriangleContact& b) { return c.t1 > b.t1; });
  }
  std::vector<ContactHint> hints;
  for (const auto& [key, best] : extremes)
    for (const TriangleContact* c : best)
      hints.push_back({c->part_a, c->triangle_a, c->part_b, c->triangle_b, (c->t0 + c->t1) / 2});
  return hints;
}

}  // namespace reconfig::collision::detail
