#pragma once
/// @file
/// Work items of the traversal (a pair of tree nodes of a pair timeline over a range of its
/// samples), what an item reads of the contacts found so far and where its own go, and how far
/// the contacts an item could still find may stick out of the groups known: the measure that
/// prunes items and orders the rest.

#include <Eigen/Geometry>
#include <algorithm>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

#include "collision/detail/frame_contacts.h"
#include "collision/detail/traversal_inputs.h"
#include "reconfig/collision/triangle_contact.h"

namespace reconfig::collision::detail {

struct WorkItem {
  int pair = 0;
  int node_a = 0, node_b = 0;
  int s0 = 0, s1 = 0;  ///< sample range of the pair timeline (s1 > s0)
};

/// The groups of the contacts found in one proxy step, per frame the step overlaps.
using StepGroups = std::vector<FrameContacts>;

/// A contact and the pair timeline it was found on.
struct LineContact {
  int line = 0;
  TriangleContact contact;
};

/// What one work item reads of the contacts found so far, and where its own contacts go.
/// Pruning relies only on the groups of contacts found in the same proxy step, so that what a
/// step finds stands on its own (an update drops and re-finds whole steps).
struct ItemContext {
  /// The groups found so far in one step of a pair timeline, or null if none.
  std::function<const StepGroups*(int line, int step)> step_groups;
  std::vector<LineContact>& contacts;  ///< contacts the item finds, clipped to frames
  DetectionStats& stats;
};

/// The frame a contact clipped to frames lies in.
inline int frame_of_contact(const FrameGrid& grid, const TriangleContact& c) { return grid.frame_of((c.t0 + c.t1) / 2); }

/// The frames an item may report contacts in: those its time range overlaps for a positive
/// time (an instant contact at its start on a frame boundary belongs to the frame on the left,
/// where the previous step reports it).
template <DopFamily family>
std::pair<int, int> item_frames(const TraversalInputs<family>& inputs, const WorkItem& item) {
  return {inputs.step_frames[item.pair][item.s0].first, inputs.step_frames[item.pair][item.s1 - 1].second};
}

/// How far the contacts the item could find might lie outside the groups of its step (for an
/// item over one step; infinite for longer items), given that it can find contacts only during
/// [from, to] (within its range): in each frame k, within [from, to] clipped to the frame,
/// [t0, t1], and within `box_between(t0, t1)`, the box where the item's contacts over that
/// time can lie (empty if the two nodes cannot meet then), the `FrameContacts::protrusion` of
/// that box; the largest over the frames. 0 if every contact the item could find would fall
/// inside a group, or there is none to find. The frames after one whose protrusion reaches
/// `enough` are left out (a caller asking only whether it is 0 passes the least double).
template <DopFamily family>
double protrusion(const TraversalInputs<family>& inputs, const WorkItem& item, const ItemContext& context,
                  const auto& box_between, double from, double to, double enough = std::numeric_limits<double>::infinity()) {
  constexpr double kUnknown = std::numeric_limits<double>::infinity();
  const auto [first, last] = item_frames(inputs, item);  // `first`: that of the item's step groups
  const StepGroups* groups = item.s1 - item.s0 == 1 ? context.step_groups(item.pair, item.s0) : nullptr;
  double largest = 0;
  for (int k = first; k <= last; ++k) {
    const double t0 = std::max(from, inputs.grid.lo(k)), t1 = std::min(to, inputs.grid.hi(k));
    if (t0 > t1) continue;
    const Eigen::AlignedBox3d box = box_between(t0, t1);
    if (box.isEmpty()) continue;
    if (inputs.options.all_contacts || !groups) return kUnknown;
    largest = std::max(largest, (*groups)[k - first].protrusion(t0, t1, box));
    if (largest >= enough) return largest;
  }
  return largest;
}

/// The least positive double: a protrusion threshold that asks only whether an item sticks out
/// of the groups at all.
inline constexpr double kAnyProtrusion = std::numeric_limits<double>::denorm_min();

}  // namespace reconfig::collision::detail
