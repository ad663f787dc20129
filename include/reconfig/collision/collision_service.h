#pragma once
/// @file
/// Continuous collision detection for an editor: a background thread keeps the collision
/// intervals of every transition up to date as edits arrive, never blocking the caller
/// (reconfigurables §4.1, §5).

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "reconfig/collision/interval_diff.h"
#include "reconfig/collision/spacetime_detector.h"
#include "reconfig/scene/dirty_set.h"
#include "reconfig/scene/reconfigurable.h"

namespace reconfig::collision {

/// What the service knows about one transition at one moment.
struct TransitionSnapshot {
  int transition = 0;
  std::string name;
  std::vector<CollisionInterval> intervals;  ///< maximal consolidation (timeline, graph badges)
  std::vector<CollisionInterval> frames;     ///< consolidation bounded to one frame (3D boxes)
  /// While this transition is being re-detected: the coarse time ranges where collisions may
  /// still be found (the faint timeline previews), refined level by level. Empty when done.
  std::vector<std::pair<double, double>> preview;
  bool up_to_date = false;  ///< describes the snapshot's scene version
  /// How `intervals` changed since the last up-to-date result of this transition, in the order
  /// a designer should hear about it.
  std::vector<IntervalDiffEntry> changes;
};

/// An immutable picture, safe to read from any thread while the service moves on.
struct CollisionSnapshot {
  std::uint64_t version = 0;  ///< the submitted scene version it describes (0: none yet)
  bool complete = false;      ///< every transition is up to date for `version`
  std::vector<TransitionSnapshot> transitions;
  DetectionStats stats;       ///< of the last detection run
};

struct CollisionServiceOptions {
  DetectorOptions detector;
  /// Threads detection may use (0: all cores). An editor leaves a core to its UI and renderer.
  int max_threads = 0;
  /// Run the worker at a lower scheduling priority (Linux nice +10), so that when the UI
  /// needs the CPU it gets it first.
  bool background_priority = false;
};

class CollisionService {
 public:
  explicit CollisionService(CollisionServiceOptions options = {});
  /// Stops the worker (abandoning unfinished work).
  ~CollisionService();
  CollisionService(const CollisionService&) = delete;
  CollisionService& operator=(const CollisionService&) = delete;

  /// Hands over a new version of the design and what changed since the previously submitted
  /// one (an empty set with `structure_changed` for the first). Returns at once; work on an
  /// older version is cancelled at its next check and the dirty sets are merged. A change of
  /// structure (parts or transitions renumbered) replaces the picture at once by an empty one
  /// for this version, and pictures of older versions are no longer published: no picture
  /// names a part or transition by an index of another numbering.
  /// @return the version number of this submission (1, 2, …)
  std::uint64_t submit(std::shared_ptr<const scene::Reconfigurable> scene, const scene::DirtySet& dirty);

  /// The latest published picture (never null).
  std::shared_ptr<const CollisionSnapshot> snapshot() const;

  /// Waits until the latest submitted version is complete, or the timeout passes.
  /// @return whether it completed
  bool wait_until_complete(std::chrono::milliseconds timeout) const;

 private:
  void run();
  void publish(std::shared_ptr<const CollisionSnapshot> next);

  CollisionServiceOptions options_;
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::shared_ptr<const scene::Reconfigurable> pending_scene_;
  scene::DirtySet pending_dirty_;
  std::uint64_t submitted_ = 0;
  std::uint64_t renumbered_ = 0;  ///< the latest submission whose structure changed
  bool stopping_ = false;
  std::shared_ptr<const CollisionSnapshot> snapshot_;
  std::thread worker_;
};

}  // namespace reconfig::collision
