#include "collision/detail/frame_contacts.h"

#include <algorithm>
#include <limits>

#include "collision/detail/interval_merging.h"
#include "reconfig/collision/consolidate.h"

namespace reconfig::collision::detail {

void FrameContacts::add(const TriangleContact& contact) {
  CollisionInterval grown = witnesses_ ? contact_interval(contact)
                                       : CollisionInterval{contact.t0, contact.t1, {}, contact.box, false, contact.possible, {}};
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

namespace {

/// `out` over `size`; the largest double when `size` is 0 and `out` is not.
double relative(double out, double size) {
  if (out == 0) return 0;
  return size > 0 ? out / size : std::numeric_limits<double>::max();
}

}  // namespace

double FrameContacts::protrusion(double t0, double t1, const Eigen::AlignedBox3d& box) const {
  double least = std::numeric_limits<double>::infinity();
  const double duration = t1 - t0, side = box.sizes().maxCoeff();
  for (const CollisionInterval& g : groups_) {
    if (g.possible) continue;
    const double out_time = std::max({g.t0 - t0, t1 - g.t1, 0.0});
    const double out_space = std::max({(g.box.min() - box.min()).maxCoeff(), (box.max() - g.box.max()).maxCoeff(), 0.0});
    least = std::min(least, std::max(relative(out_time, duration), relative(out_space, side)));
  }
  return least;
}

}  // namespace reconfig::collision::detail
