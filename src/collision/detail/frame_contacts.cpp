#include "collision/detail/frame_contacts.h"

#include <algorithm>

#include "collision/detail/interval_merging.h"
#include "reconfig/collision/consolidate.h"

namespace reconfig::collision::detail {

void FrameContacts::add(const TriangleContact& contact) {
  CollisionInterval grown = contact_interval(contact);
  // A group that grew may meet groups it did not meet before: merge until it meets none.
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t g = 0; g < groups_.size(); ++g)
      if (intervals_meet(groups_[g], grown, gap_)) {
        absorb(grown, groups_[g]);
        groups_.erase(groups_.begin() + static_cast<std::ptrdiff_t>(g));
        merged = true;
        break;
      }
  }
  groups_.push_back(std::move(grown));
}

bool FrameContacts::covers(double t0, double t1, const Eigen::AlignedBox3d& box) const {
  return std::any_of(groups_.begin(), groups_.end(), [&](const CollisionInterval& g) {
    return !g.possible && g.t0 <= t0 && t1 <= g.t1 && g.box.contains(box);
  });
}

}  // namespace reconfig::collision::detail
