#include "reconfig/collision/collision_service.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include "reconfig/collision/consolidate.h"

namespace reconfig::collision {
namespace {

/// A picture of `scene` at `version` before any detection: each transition named, nothing found.
std::shared_ptr<const CollisionSnapshot> undetected(const scene::Reconfigurable& scene, std::uint64_t version) {
  auto snapshot = std::make_shared<CollisionSnapshot>();
  snapshot->version = version;
  snapshot->transitions.resize(scene.transitions.size());
  for (std::size_t t = 0; t < scene.transitions.size(); ++t) {
    snapshot->transitions[t].transition = static_cast<int>(t);
    snapshot->transitions[t].name = scene.transitions[t].name;
  }
  return snapshot;
}

}  // namespace

CollisionService::CollisionService(CollisionServiceOptions options)
    : options_(options), snapshot_(std::make_shared<CollisionSnapshot>()) {
  worker_ = std::thread([this] {
    if (options_.background_priority) setpriority(PRIO_PROCESS, static_cast<id_t>(::syscall(SYS_gettid)), 10);
    // With a limited arena every parallel loop of the detection runs on this (niced) thread
    // and at most max_threads − 1 others.
    tbb::task_arena arena(options_.max_threads > 0 ? options_.max_threads : tbb::task_arena::automatic);
    arena.execute([this] { run(); });
  });
}

CollisionService::~CollisionService() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  worker_.join();
}

std::uint64_t CollisionService::submit(std::shared_ptr<const scene::Reconfigurable> scene,
                                       const scene::DirtySet& dirty) {
  std::lock_guard lock(mutex_);
  ++submitted_;
  if (dirty.structure_changed) {  // the old picture's indices mean other parts now
    renumbered_ = submitted_;
    snapshot_ = undetected(*scene, submitted_);
  }
  pending_scene_ = std::move(scene);
  pending_dirty_.merge(dirty);
  changed_.notify_all();
  return submitted_;
}

std::shared_ptr<const CollisionSnapshot> CollisionService::snapshot() const {
  std::lock_guard lock(mutex_);
  return snapshot_;
}

bool CollisionService::wait_until_complete(std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mutex_);
  return changed_.wait_for(lock, timeout, [&] { return snapshot_->complete && snapshot_->version == submitted_; });
}

void CollisionService::publish(std::shared_ptr<const CollisionSnapshot> next) {
  {
    std::lock_guard lock(mutex_);
    if (next->version < renumbered_) return;  // a round on the old numbering
    snapshot_ = std::move(next);
  }
  changed_.notify_all();
}

void CollisionService::run() {
  std::vector<SpacetimeDetector> detectors;
  BodyTrees trees;
  std::vector<TransitionSnapshot> last_done;  // per transition: the last up-to-date result
  for (;;) {
    std::shared_ptr<const scene::Reconfigurable> scene;
    scene::DirtySet dirty;
    std::uint64_t version = 0;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [&] { return stopping_ || pending_scene_ != nullptr; });
      if (stopping_) return;
      scene = std::move(pending_scene_);
      pending_scene_ = nullptr;
      dirty = std::move(pending_dirty_);
      pending_dirty_ = {};
      version = submitted_;
    }
    // A newer submission cancels this round; its dirty set is merged with ours below.
    const auto superseded = [&] {
      std::lock_guard lock(mutex_);
      return stopping_ || pending_scene_ != nullptr;
    };
    const int n = static_cast<int>(scene->transitions.size());
    // Transitions appended at the end get detectors of their own (a new detector detects from
    // scratch at its first update); the others keep theirs.
    const bool appended = !dirty.added_transitions.empty() && !dirty.structure_changed &&
                          static_cast<int>(detectors.size() + dirty.added_transitions.size()) == n;
    if (appended && trees.size() == scene->parts.size()) {
      for (int t = static_cast<int>(detectors.size()); t < n; ++t) detectors.emplace_back(t, options_.detector);
      last_done.resize(n);
    }
    const bool rebuild = dirty.structure_changed || static_cast<int>(detectors.size()) != n ||
                         trees.size() != scene->parts.size();
    if (rebuild) {
      trees = build_body_trees(*scene);
      detectors.clear();
      for (int t = 0; t < n; ++t) detectors.emplace_back(t, options_.detector);
      last_done.assign(n, {});
    } else {
      for (int part : dirty.geometry_changed) trees[part] = std::make_shared<const BodyTree>(scene->parts[part].mesh);
    }
    auto current = std::make_shared<CollisionSnapshot>(*snapshot());
    current->version = version;
    current->complete = false;
    current->transitions.resize(n);
    for (int t = 0; t < n; ++t) {
      // Entries not detected yet still name their transition (a resize default-constructs them).
      current->transitions[t].transition = t;
      current->transitions[t].name = scene->transitions[t].name;
      current->transitions[t].up_to_date = false;
    }
    bool cancelled = false;
    for (int t = 0; t < n && !cancelled; ++t) {
      DetectCallbacks callbacks;
      callbacks.progress = [&](double) { return !superseded(); };
      callbacks.preview = [&](const TraversalPreview& preview) {
        auto next = std::make_shared<CollisionSnapshot>(*current);
        next->transitions[t].preview = preview.ranges;
        publish(next);
      };
      const bool done = rebuild ? detectors[t].detect(*scene, trees, callbacks)
                                : detectors[t].update(*scene, trees, dirty, callbacks);
      if (!done) {
        cancelled = true;
        break;
      }
      TransitionSnapshot result;
      result.transition = t;
      result.name = scene->transitions[t].name;
      result.intervals = consolidate(detectors[t].intervals(), detectors[t].containments());
      result.frames = consolidate(detectors[t].intervals(), detectors[t].containments(), options_.detector.frame);
      result.up_to_date = true;
      result.changes = diff_intervals(last_done[t].intervals, result.intervals);
      last_done[t] = result;
      current->transitions[t] = std::move(result);
      current->stats = detectors[t].last_stats();
      publish(std::make_shared<CollisionSnapshot>(*current));
    }
    if (cancelled) {
      // Detectors that did not finish are invalid and will detect from scratch; keep the
      // dirty set for the ones that did not run yet.
      std::lock_guard lock(mutex_);
      pending_dirty_.merge(dirty);
      continue;
    }
    current->complete = true;
    publish(current);
  }
}

}  // namespace reconfig::collision
