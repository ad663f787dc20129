#include "collision/detail/frame_contacts.h"

#include "collision/detail/interval_merging.h"
#include "reconfig/collision/consolidate.h"

namespace reconfig::collision::detail {

void FrameContacts::add(const TriangleContact& contact) {
  CollisionInterval grown = contact_interval(contact);
  // A group that grew may meet groups it did not meet before: merge until it meets none.
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t g = 0; g < groups_.size(); ++g)
      if (times_meet(groups_[g], grown) && boxes_meet(groups_[g].box, grown.box, gap_)) {
        absorb(grown, groups_[g]);
        groups_.erase(groups_.begin() + static_cast<std::ptrdiff_t>(g));
        merged = true;
        break;
      }
  }
  groups_.push_back(std::move(grown));
}

bool FrameContacts::covers(double t0, double t1, const Eigen::AlignedBox3d& box) const {
  for (const CollisionInterval& group : groups_)
    if (!group.possible && group.t0 <= t0 && t1 <= group.t1 && group.box.contains(box)) return true;
  return false;
}

bool FrameContacts::covers_time(double t0, double t1) const {
  for (const CollisionInterval& group : groups_)
    if (!group.possible && group.t0 <= t0 && t1 <= group.t1) return true;
  return false;
}

}  // namespace reconfig::collision::detail
