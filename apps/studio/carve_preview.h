#pragma once
/// @file
/// The Carve window's preview: the volume the chosen carvers sweep through the carved part,
/// in that part's rest frame (what a carve would subtract), computed in the background with
/// progress and cancel, and recomputed when the design, the carvers, the offset or the grid
/// change (a result for anything else is dropped).

#include <atomic>
#include <cstdint>
#include <future>
#include <memory>
#include <optional>
#include <vector>

#include "reconfig/geometry/mesh.h"
#include "reconfig/scene/reconfigurable.h"

namespace reconfig::studio {

class CarvePreview {
 public:
  /// What a preview is of.
  struct Key {
    std::uint64_t version = 0;  ///< of the design
    int transition = -1, part = -1;
    std::vector<int> carvers;
    double offset = 0, grid = 0;
    double from = 0, to = 1;  ///< the time range of the transition that carves
    bool operator==(const Key&) const = default;
  };

  /// Keeps the preview of `key` shown or on its way: a running job for another key is
  /// cancelled and one for `key` started (nothing when there are no carvers).
  /// @param scene  the design at `key.version`, kept alive by the job
  void request(std::shared_ptr<const scene::Reconfigurable> scene, const Key& key);
  /// Takes a finished job's mesh (each frame).
  void update();
  /// Cancels the job and hides the preview.
  void clear();

  bool computing() const { return job_ != nullptr; }
  double progress() const { return job_ ? job_->progress.load() : 0.0; }
  /// The swept volumes of the shown key's carvers, in the part's rest frame (null: none yet).
  const std::shared_ptr<const geometry::Mesh>& mesh() const { return mesh_; }
  /// The key `mesh` is of.
  const std::optional<Key>& shown() const { return shown_; }
  /// Changes whenever the mesh shown does (for redrawing).
  std::uint64_t revision() const { return revision_; }

 private:
  struct Job {
    ~Job() { cancel = true; }  // before the future waits for the thread to end
    Key key;
    std::atomic<double> progress{0};
    std::atomic<bool> cancel{false};
    std::future<std::optional<geometry::Mesh>> result;  ///< none when cancelled
  };
  std::unique_ptr<Job> job_;
  std::optional<Key> shown_;
  std::shared_ptr<const geometry::Mesh> mesh_;
  std::uint64_t revision_ = 0;
};

}  // namespace reconfig::studio
