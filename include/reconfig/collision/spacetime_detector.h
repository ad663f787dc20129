#pragma once
/// @file
/// The spacetime collision detector of one transition: a 4D k-DOP bounding volume hierarchy
/// over the parts' spacetime proxies, traversed breadth first ("time first": coarse time
/// extents of possible collisions are known level by level), then depth first one proxy step
/// at a time, with an exact narrow phase at the leaves, and local refitting after edits
/// (reconfigurables §5). Contacts are merged per pair of parts and frame into groups, and the
/// traversal skips whatever could only add contacts inside a group it already has, so a deep
/// overlap costs its witnesses rather than every intersecting triangle pair.

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "reconfig/collision/body_tree.h"
#include "reconfig/collision/collision_interval.h"
#include "reconfig/collision/kdop.h"
#include "reconfig/collision/spacetime_proxy.h"
#include "reconfig/collision/triangle_contact.h"
#include "reconfig/common/progress.h"
#include "reconfig/scene/dirty_set.h"
#include "reconfig/scene/reconfigurable.h"

namespace reconfig::collision {

struct DetectorOptions {
  /// Largest distance between a proxy and the true motion, in scene units (> 0).
  double tolerance = 1e-3;
  DopFamily dop = DopFamily::k28;
  /// Inflate every bound by the proxies' deviation and report leaf pairs whose inflated
  /// bounds meet as `possible` contacts, so no collision of the true continuous motion is
  /// missed (at the price of near misses reported).
  bool conservative = false;
  /// Also report parts nested inside others without surface contact.
  bool detect_containment = true;
  /// The contact tolerance δ, in scene units (0: `kDefaultContact` of the design's size,
  /// `contact_tolerance.h`): triangles that only touch within δ (`triangle_touching.h`) are
  /// not a collision.
  double contact = 0;
  /// Report touching (surfaces within δ, interiors not overlapping beyond it) as a collision too.
  bool touching_collides = false;
  /// Also report where two parts come closer than this, in scene units, without interfering,
  /// as clearance intervals (`SpacetimeDetector::clearances`; 0: no clearance check). A second
  /// traversal finds them: bounds grown by half of it on each side, `triangles_closer_than` at
  /// the leaves, ends refined like collision ends; the collision intervals are then taken out.
  double clearance = 0;
  /// Find where parts come closer than this distance instead of where they interfere (0:
  /// interference). The clearance check's own traversal sets it; a caller sets `clearance`.
  double closer_than = 0;
  double min_step = 1e-5;  ///< smallest proxy time step
  /// Length of a frame (`FrameGrid`): contacts are clipped to frames and merged into groups
  /// per pair of parts and frame, so every group spans one frame at most and the 3D view's
  /// boxes stay tight.
  double frame = 0.01;
  /// Find every intersecting triangle pair (all of a deep overlap's hundreds of thousands).
  /// Off, the traversal skips any work whose contacts could only fall inside a group the
  /// frame already has (its time and box): the groups — when, where, which parts — come out
  /// the same, and each group's triangle list holds the contacts that made it (witnesses).
  bool all_contacts = false;
  /// Contacts of a pair of parts in one frame whose boxes come closer than this fraction of
  /// the smaller part's size (its box diagonal) form one group.
  double group_gap = 0.2;
  /// Contact boxes are rounded outward to a grid whose cells measure this fraction of the
  /// smaller part's size (box diagonal): each group's box contains every contact's exactly and
  /// is at most one cell larger on each side. The traversal then skips any work whose
  /// contacts could only fall inside a group's rounded box, which is much more of it than
  /// with exact boxes (0: exact boxes).
  double box_resolution = 0.02;
  /// The traversal goes breadth first (a preview per level) while a level holds fewer work
  /// items than this, then one proxy step at a time, so that the contacts a step finds prune
  /// the rest of it at once (breadth first, work over several steps prunes nothing: on the
  /// kitchen, 8192 here made an update three times slower than 64).
  std::size_t breadth_first_items = 64;
};

/// How close the detector's interval ends lie to the true ones, as a fraction of the
/// transition (outside them, or up to where the triangles come within the narrow phase's
/// distance tolerance); conservative mode does not refine its ends.
inline constexpr double kIntervalEndTolerance = 1e-6;

/// The coarse picture after one level of the breadth-first traversal: every time where a
/// collision may still be found lies in one of `ranges` (sorted, disjoint).
struct TraversalPreview {
  int level = 0;
  std::vector<std::pair<double, double>> ranges;
};

struct DetectionStats {
  long bound_tests = 0;     ///< k-DOP pair overlap tests
  long narrow_phase = 0;    ///< triangle-pair continuous tests (leaf pairs whose k-DOPs meet in some eighth of the step)
  long narrow_pieces = 0;   ///< time pieces the narrow phase examined
  long contact_tests = 0;   ///< vertex–face and edge–edge tests the narrow phase ran
  long containment_tests = 0;
  long pruned = 0;          ///< work skipped: its contacts would fall inside groups found already, or its nodes meet in no frame
  int levels = 0;           ///< breadth-first levels processed
  long proxy_samples = 0;   ///< time samples over all parts' proxies
  long end_refinements = 0;  ///< re-detections of time windows that refined intervals' ends

  /// Sums the counts (`levels`: the largest).
  DetectionStats& operator+=(const DetectionStats& other);
};

/// Called during a detection from any of its threads, one call at a time and in order,
/// before `detect` or `update` returns.
struct DetectCallbacks {
  ProgressCallback progress;                              ///< fraction done; false cancels
  /// After each breadth-first level, then after every few proxy steps of the depth-first phase.
  std::function<void(const TraversalPreview&)> preview;
};

/// The one piece of per-part data shared by every transition: its body-frame tree.
using BodyTrees = std::vector<std::shared_ptr<const BodyTree>>;

/// Builds the body trees of every part.
BodyTrees build_body_trees(const scene::Reconfigurable& scene);

/// Detection state of one transition, kept between edits so that an edit costs only the
/// re-traversal of what it dirtied.
class SpacetimeDetector {
 public:
  SpacetimeDetector(int transition, DetectorOptions options);

  /// Builds every part's proxy and finds every contact over the whole transition.
  /// @return false if cancelled (the detector then holds no valid result)
  bool detect(const scene::Reconfigurable& scene, const BodyTrees& trees, const DetectCallbacks& callbacks = {});

  /// Brings the result up to date after edits: rebuilds the proxies of the parts the dirty set
  /// names for this transition, finds the time range where each proxy changed, drops the
  /// contacts found in those stretches and re-traverses only the pairs involving a changed
  /// part over them, starting from the triangle pairs of the dropped contacts that made their
  /// groups' extents (after a small edit they most likely make the new extents, which then
  /// prune the rest early). The groups are the same as those of `detect` from scratch (the
  /// contacts that stand for them may differ). Parts whose geometry
  /// changed (or a structural change) trigger a full `detect`.
  /// @return false if cancelled (call `detect` before trusting the result again)
  bool update(const scene::Reconfigurable& scene, const BodyTrees& trees, const scene::DirtySet& dirty,
              const DetectCallbacks& callbacks = {});

  int transition() const { return transition_; }
  const DetectorOptions& options() const { return options_; }
  bool valid() const { return valid_; }
  /// Per pair of parts and frame, the contacts merged into groups (the detection's result),
  /// sorted by (t0, parts, t1). Each group's `parts` are its two parts.
  const std::vector<CollisionInterval>& groups() const { return groups_; }
  /// The triangle contacts found, clipped to frames, sorted by (t0, parts, triangles): every
  /// one with `all_contacts`, else the witnesses the groups are made of.
  const std::vector<TriangleContact>& contacts() const { return contacts_; }
  const std::vector<Containment>& containments() const { return containments_; }
  /// With `DetectorOptions::clearance`: per pair of parts and frame, the times the parts come
  /// closer than the clearance without interfering (their groups' times less the collision
  /// intervals and containments of the pair), flagged `clearance`, sorted like `groups`.
  const std::vector<CollisionInterval>& clearances() const { return clearances_; }
  /// The groups, then the clearances: every interval a designer is told of (to consolidate).
  std::vector<CollisionInterval> intervals() const;
  const std::vector<PartProxy>& proxies() const { return proxies_; }
  const DetectionStats& last_stats() const { return stats_; }

 private:
  struct PairRange {
    int a, b;       ///< parts, a < b
    double t0, t1;  ///< time range to traverse (proxy sample times, or 0 and 1)
  };
  /// Per part whose proxy an update changed: the time ranges where it changed.
  using ChangedRanges = std::map<int, std::vector<std::pair<double, double>>>;
  /// With the proxies built: finds every contact over the whole transition.
  bool traverse_all(const scene::Reconfigurable& scene, const BodyTrees& trees, const DetectCallbacks& callbacks);
  /// With the proxies rebuilt: re-traverses the pairs of the changed parts where they changed.
  bool retraverse_changed(const scene::Reconfigurable& scene, const BodyTrees& trees, const ChangedRanges& changed,
                          const DetectCallbacks& callbacks);
  /// @param previous  the contacts an earlier result had in `work`: the search starts from the
  ///                  triangle pairs that made their groups' extents
  bool traverse(const scene::Reconfigurable& scene, const BodyTrees& trees, const std::vector<PairRange>& work,
                const std::vector<TriangleContact>& previous, const DetectCallbacks& callbacks);
  /// After `detect` (`changed` null) or `update` of the collisions: the same for the clearance
  /// traversal, on this detector's proxies, and `clearances_` from both.
  bool check_clearance(const scene::Reconfigurable& scene, const BodyTrees& trees, const ChangedRanges* changed,
                       const DetectCallbacks& callbacks);

  int transition_;
  DetectorOptions options_;
  bool valid_ = false;
  std::vector<PartProxy> proxies_;
  std::vector<CollisionInterval> groups_;
  std::vector<TriangleContact> contacts_;
  std::vector<Containment> containments_;
  /// The clearance check's traversal (`closer_than` set), with `DetectorOptions::clearance`.
  std::unique_ptr<SpacetimeDetector> closer_;
  std::vector<CollisionInterval> clearances_;
  DetectionStats stats_;
};

}  // namespace reconfig::collision
