#pragma once
/// @file
/// The traversal behind `SpacetimeDetector`: pairs of parts over time ranges, their 4D k-DOP
/// hierarchies walked breadth first then depth first per proxy step, the narrow phase at the
/// leaves, and the grouping of the contacts found per pair of parts and frame.
///
/// Its parts, each in its own header: pair timelines (`pair_timeline.h`), what every thread
/// reads and the node bounds (`traversal_inputs.h`), the bound cache (`bound_cache.h`), work
/// items and their protrusion (`work_item.h`), one item looked at (`work_item_expansion.h`),
/// the leaf narrow phase (`leaf_narrow_phase.h`), contact hints (`contact_hints.h`) and the
/// step scheduler (`step_scheduler.h`).

#include <utility>
#include <vector>

#include "reconfig/collision/collision_interval.h"
#include "reconfig/collision/frame_grid.h"
#include "reconfig/collision/spacetime_detector.h"

namespace reconfig::collision::detail {

/// One pair of parts (a < b) to traverse over [t0, t1] (proxy sample times, or 0 and 1, so
/// that the steps are those of the whole transition).
struct TraversalRange {
  int a = 0, b = 0;
  double t0 = 0, t1 = 1;
};

/// The pairs of parts (a < b) over [0, 1] whose sweeps over the whole transition may meet —
/// the bound `traverse_ranges` tests each range with first — found by a sweep and prune along
/// the bounds' first axis: time and memory grow with the parts and the pairs found, not with
/// the square of the parts (10,000 parts: 5e7 pairs). Sorted by (a, b).
std::vector<TraversalRange> candidate_pairs(const BodyTrees& trees, const std::vector<PartProxy>& proxies,
                                            const scene::Reconfigurable& scene, const DetectorOptions& options);

/// A pair of triangles (of parts a < b) that was in contact at time t in an earlier result.
struct ContactHint {
  int part_a = 0, triangle_a = 0;
  int part_b = 0, triangle_b = 0;
  double t = 0;
};

/// Finds the contacts of every range, sorted by `contact_less`, adding to `stats`.
/// `hints` warm-start the search: in the proxy step that holds a hint's time, the narrow phase
/// runs on its triangle pair before anything else, so that the groups it finds there prune
/// early (a contact a hint finds is a contact like any other; the groups found do not depend on
/// the hints, only how soon they are reached and which contacts stand for them).
/// @param pad  the padding of the bounds against rounding (`traversal_pad`; 0: computed here)
/// @return false if cancelled through `callbacks.progress`
bool traverse_ranges(const scene::Reconfigurable& scene, const BodyTrees& trees, const std::vector<PartProxy>& proxies,
                     const DetectorOptions& options, const std::vector<TraversalRange>& ranges,
                     const std::vector<ContactHint>& hints, std::vector<TriangleContact>& contacts, DetectionStats& stats,
                     const DetectCallbacks& callbacks, double pad = 0);

/// The absolute padding of every bound against the rounding of bound arithmetic: a multiple of
/// the machine epsilon times the largest coordinate of any rest vertex or placement.
double traversal_pad(const scene::Reconfigurable& scene, const std::vector<PartProxy>& proxies);

/// Hints for a search that must find `contacts` again (or their successors after an edit):
/// per pair of parts and frame, the contacts whose boxes reach furthest along each axis, either
/// way, and those that start first and end last: those the groups' extents come from.
std::vector<ContactHint> extreme_contacts(const std::vector<TriangleContact>& contacts, const FrameGrid& grid);

/// The groups of every pair of parts and frame: the contacts that meet (in time, and in space
/// within the options' `group_gap`) merged to the fixpoint, sorted by (t0, parts, t1).
std::vector<CollisionInterval> group_contacts(const std::vector<TriangleContact>& contacts,
                                              const DetectorOptions& options, const BodyTrees& trees);

/// The order of contacts: (t0, parts, triangles, t1).
bool contact_less(const TriangleContact& x, const TriangleContact& y);

/// Sorted, disjoint union of time ranges.
std::vector<std::pair<double, double>> union_of(std::vector<std::pair<double, double>> ranges);

/// The posed (proxy) vertices of a part at time t.
Eigen::MatrixX3d proxy_vertices(const scene::Reconfigurable& scene, const PartProxy& proxy, int part, double t);

/// Rest-frame points (rows) placed by a part's proxy at time t.
Eigen::MatrixX3d proxy_points(const PartProxy& proxy, const Eigen::MatrixX3d& rest, double t);

}  // namespace reconfig::collision::detail
