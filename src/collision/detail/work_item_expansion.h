#pragma once
/// @file
/// One work item looked at: its nodes' spacetime k-DOPs tested (and, within one step, when and
/// where the nodes can meet, against the groups found so far), then the item pruned, split in
/// time or space into children, or, for two leaves, handed to the leaf narrow phase.

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "collision/detail/bound_cache.h"
#include "collision/detail/leaf_narrow_phase.h"
#include "collision/detail/work_item.h"

namespace reconfig::collision::detail {

/// Two leaves over at most this many steps are bounded step by step.
inline constexpr int kStepwiseLeafSteps = 8;

/// The largest spatial extent of a k-DOP (along x, y or z).
template <DopFamily family>
double spatial_extent(const Kdop<family>& dop) {
  return std::max({dop.hi[0] - dop.lo[0], dop.hi[1] - dop.lo[1], dop.hi[2] - dop.lo[2]});
}

/// Looks at one work item: prunes it, splits it into `children`, or runs the narrow phase.
/// @return the item's `protrusion` when it was split (its children's urgency until they are
///         looked at), else 0
template <DopFamily family>
double expand_work_item(const TraversalInputs<family>& inputs, const WorkItem& item, std::vector<WorkItem>& children,
                        const ItemContext& context, const BoundLookup<family>& bounds) {
  DetectionStats& stats = context.stats;
  const PairTimeline& line = inputs.lines[item.pair];
  const BodyTree::Node& na = inputs.tree(item.pair, 0).node(item.node_a);
  const BodyTree::Node& nb = inputs.tree(item.pair, 1).node(item.node_b);
  const bool single_step = item.s1 - item.s0 == 1;
  const double growth_a = inputs.growth(item.pair, 0), growth_b = inputs.growth(item.pair, 1);
  const Kdop<family>* da = nullptr;  // the nodes' k-DOPs over the range (in the bound cache)
  const Kdop<family>* db = nullptr;
  double urgency = std::numeric_limits<double>::infinity();
  if (!(na.leaf() && nb.leaf() && single_step)) {  // that case is culled by `meeting_pieces`, tighter
    ++stats.bound_tests;
    // The k-DOPs over the range, and at the ends of a single step.
    const auto& bound_a = bounds.get(inputs, item.pair, 0, item.node_a, item.s0, item.s1);
    const auto& bound_b = bounds.get(inputs, item.pair, 1, item.node_b, item.s0, item.s1);
    da = &bound_a.dop;
    db = &bound_b.dop;
    const std::array<Kdop<family>, 2>& ends_a = bound_a.ends;
    const std::array<Kdop<family>, 2>& ends_b = bound_b.ends;
    if (!da->overlaps(*db)) return 0;
    const double step_t0 = line.times[item.s0], step_t1 = line.times[item.s1];
    double meet_t0 = step_t0, meet_t1 = step_t1;  // when the nodes may meet
    if (single_step) {
      const auto [mu0, mu1] = meeting_range(ends_a, ends_b);
      if (mu0 > mu1) return 0;
      // The narrow phase may report a contact over a whole piece of its grid, beyond the times
      // the triangles meet: the item's contacts lie within the pieces that [mu0, mu1] touches.
      const double piece0 = std::floor(mu0 * kNarrowPieces), piece1 = std::ceil(mu1 * kNarrowPieces);
      if (piece0 > 0) meet_t0 = step_t0 + piece0 / kNarrowPieces * (step_t1 - step_t0);
      if (piece1 < kNarrowPieces) meet_t1 = std::min(step_t1, step_t0 + piece1 / kNarrowPieces * (step_t1 - step_t0));
    }
    const auto box_between = [&](double t0, double t1) {
      if (t0 <= step_t0 && t1 >= step_t1) return spatial_box(*da).intersection(spatial_box(*db));
      if (single_step) {
        // Within one step a node's box at a time lies within the interpolation of its boxes at
        // the step's ends (its center moves linearly, and its reach |L|·half is convex in time),
        // so over [t0, t1] within the hull of those interpolations at t0 and t1.
        const double mu0 = std::max(0.0, (t0 - step_t0) / (step_t1 - step_t0)), mu1 = std::min(1.0, (t1 - step_t0) / (step_t1 - step_t0));
        const auto sweep = [&](const std::array<Kdop<family>, 2>& ends) {
          const Eigen::AlignedBox3d box0 = spatial_box(ends[0]), box1 = spatial_box(ends[1]);
          const auto lerp = [&](double mu) {
            return Eigen::AlignedBox3d((1 - mu) * box0.min() + mu * box1.min(), (1 - mu) * box0.max() + mu * box1.max());
          };
          return lerp(mu0).extend(lerp(mu1));
        };
        return inflated(sweep(ends_a), inputs.pad).intersection(inflated(sweep(ends_b), inputs.pad));
      }
      return inputs.node_box_between(item.pair, 0, item.node_a, t0, t1, growth_a)
          .intersection(inputs.node_box_between(item.pair, 1, item.node_b, t0, t1, growth_b));
    };
    urgency = protrusion(inputs, item, context, box_between, meet_t0, meet_t1);
    if (urgency == 0) {
      ++stats.pruned;
      return 0;
    }
  }
  const auto push = [&](int node_a, int node_b, int s0, int s1) { children.push_back({item.pair, node_a, node_b, s0, s1}); };
  const auto split_time = [&] {
    const int middle = (item.s0 + item.s1) / 2;
    push(item.node_a, item.node_b, item.s0, middle);
    push(item.node_a, item.node_b, middle, item.s1);
  };
  if (na.leaf() && nb.leaf()) {
    // The narrow phase of the two triangles over samples [s0, s1]: one step, or a range over
    // which both hold still.
    const auto narrow_phase = [&](int s0, int s1) {
      LeafNarrowPhase<family> leaves(inputs, context, item.pair, item.node_a, item.node_b, s0, s1);
      if (s1 - s0 == 1) leaves.search_moving_step();
      else if (!line.moving[0] && !line.moving[1]) leaves.search_still_range();
    };
    if (single_step || (!line.moving[0] && !line.moving[1])) {
      narrow_phase(item.s0, item.s1);
      return 0;
    }
    // Over a few steps, bound each step on its own: halving the range again and again would
    // bound every half over all its samples. Long ranges are halved first, as a range where the
    // triangles meet nowhere is then dropped with one test.
    if (item.s1 - item.s0 > kStepwiseLeafSteps) {
      split_time();
      return urgency;
    }
    for (int s = item.s0; s < item.s1; ++s) {
      ++stats.bound_tests;
      if (inputs.node_bound(item.pair, 0, item.node_a, s, s + 1).overlaps(inputs.node_bound(item.pair, 1, item.node_b, s, s + 1)))
        narrow_phase(s, s + 1);
    }
    return 0;
  }
  // Split the dimension that makes the bounds loose: time when the motion over the range
  // sweeps further than the nodes are large, else the larger node.
  const double size_a = 2 * na.half.maxCoeff(), size_b = 2 * nb.half.maxCoeff();
  const double sweep = std::max(spatial_extent(*da) - size_a, spatial_extent(*db) - size_b);
  if (!single_step && sweep > std::min(size_a, size_b)) {
    split_time();
  } else if (!na.leaf() && (nb.leaf() || size_a >= size_b)) {
    push(na.left, item.node_b, item.s0, item.s1);
    push(na.right, item.node_b, item.s0, item.s1);
  } else {
    push(item.node_a, nb.left, item.s0, item.s1);
    push(item.node_a, nb.right, item.s0, item.s1);
  }
  return urgency;
}

}  // namespace reconfig::collision::detail
