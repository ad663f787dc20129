#pragma once
/// @file
/// The spacetime collision detector of one transition: a 4D k-DOP bounding volume hierarchy
/// over the parts' spacetime proxies, traversed breadth first ("time first": coarse time
/// extents of possible collisions are known level by level), with an exact narrow phase at
/// the leaves, and local refitting after edits (reconfigurables §5).

#include <functional>
#include <memory>
#include <vector>

#include "reconfig/collision/body_tree.h"
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
  double min_step = 1e-5;  ///< smallest proxy time step
  /// Contacts longer than this are reported in pieces, each with its own (tighter) box, so
  /// that consolidation per frame can keep the 3D view's boxes tight.
  double max_contact_duration = 0.01;
};

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
  int levels = 0;           ///< breadth-first levels processed
  long proxy_samples = 0;   ///< time samples over all parts' proxies
};

struct DetectCallbacks {
  ProgressCallback progress;                              ///< fraction of levels; false cancels
  std::function<void(const TraversalPreview&)> preview;  ///< after each level
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
  /// part over them. The result is the same as `detect` from scratch. Parts whose geometry
  /// changed (or a structural change) trigger a full `detect`.
  /// @return false if cancelled (call `detect` before trusting the result again)
  bool update(const scene::Reconfigurable& scene, const BodyTrees& trees, const scene::DirtySet& dirty,
              const DetectCallbacks& callbacks = {});

  int transition() const { return transition_; }
  const DetectorOptions& options() const { return options_; }
  bool valid() const { return valid_; }
  /// Every triangle contact, sorted by (t0, parts, triangles).
  const std::vector<TriangleContact>& contacts() const { return contacts_; }
  const std::vector<Containment>& containments() const { return containments_; }
  const std::vector<PartProxy>& proxies() const { return proxies_; }
  const DetectionStats& last_stats() const { return stats_; }

 private:
  struct PairRange {
    int a, b;       ///< parts, a < b
    double t0, t1;  ///< time range to traverse
  };
  bool traverse(const scene::Reconfigurable& scene, const BodyTrees& trees, const std::vector<PairRange>& work,
                const DetectCallbacks& callbacks);

  int transition_;
  DetectorOptions options_;
  bool valid_ = false;
  std::vector<PartProxy> proxies_;
  std::vector<TriangleContact> contacts_;
  std::vector<Containment> containments_;
  DetectionStats stats_;
};

}  // namespace reconfig::collision
