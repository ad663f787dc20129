#pragma once
/// @file
/// Contact hints: the leaf pairs whose narrow phase a proxy step runs before anything else, so
/// that the contacts that make its groups' extents come early and prune the rest. They come
/// from an earlier result (`ContactHint`, after an edit) and from the contacts the step's
/// already searched neighbors found.

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

#include "collision/detail/spacetime_traversal.h"
#include "collision/detail/work_item.h"

namespace reconfig::collision::detail {

/// Leaf pairs whose narrow phase runs first, per pair timeline and step.
using StepLeaves = std::map<std::pair<int, int>, std::vector<std::pair<int, int>>>;

/// Sorts a step's leaf pairs and drops repeats (the order they run in is then fixed).
inline void sort_unique(std::vector<std::pair<int, int>>& pairs) {
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

/// The leaves of a hint's two triangles in the trees of pair timeline `line`.
template <DopFamily family>
std::pair<int, int> leaf_pair(const TraversalInputs<family>& inputs, int line, const ContactHint& hint) {
  return {inputs.tree(line, 0).leaf_of(hint.triangle_a), inputs.tree(line, 1).leaf_of(hint.triangle_b)};
}

/// The leaf pairs of the hints, in the step that holds each hint's time.
template <DopFamily family>
StepLeaves hinted_leaves(const TraversalInputs<family>& inputs, const std::vector<ContactHint>& hints) {
  StepLeaves leaves;
  if (inputs.options.all_contacts) return leaves;  // nothing is pruned: no order is better than another
  std::multimap<std::pair<int, int>, int> lines_of;  // the pair timelines of each pair of parts
  for (int i = 0; i < static_cast<int>(inputs.lines.size()); ++i)
    lines_of.emplace(std::pair{inputs.lines[i].a, inputs.lines[i].b}, i);
  for (const ContactHint& hint : hints) {
    const auto [begin, end] = lines_of.equal_range({hint.part_a, hint.part_b});
    for (auto at = begin; at != end; ++at) {
      const int i = at->second;
      const PairTimeline& line = inputs.lines[i];
      if (hint.t < line.times.front() || hint.t > line.times.back()) continue;
      leaves[{i, line.step_of(hint.t)}].push_back(leaf_pair(inputs, i, hint));
    }
  }
  for (auto& [step, pairs] : leaves) sort_unique(pairs);
  return leaves;
}

/// The leaf pairs of the contacts that made the extents of a neighbor's groups, found there,
/// in the frames it shares with step `step` of pair timeline `line`: contacts persist from
/// step to step (a drawer sliding past a door meets the same faces), so those pairs most
/// likely make the extents of the step's groups there too.
template <DopFamily family>
std::vector<std::pair<int, int>> neighbor_leaves(const TraversalInputs<family>& inputs, int line, int step,
                                                 const std::vector<LineContact>& found) {
  std::vector<std::pair<int, int>> leaves;
  if (inputs.options.all_contacts) return leaves;
  const auto [first, last] = inputs.step_frames[line][step];
  std::vector<TriangleContact> shared;
  for (const LineContact& c : found)
    if (const int frame = frame_of_contact(inputs.grid, c.contact); frame >= first && frame <= last) shared.push_back(c.contact);
  for (const ContactHint& hint : extreme_contacts(shared, inputs.grid)) leaves.push_back(leaf_pair(inputs, line, hint));
  return leaves;
}

}  // namespace reconfig::collision::detail
