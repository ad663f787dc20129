#pragma once
/// @file
/// One open design in the studio: the scene, its undo history, where it is saved, its autosave
/// and the collision service that keeps its collision intervals up to date.

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "reconfig/collision/collision_service.h"
#include "reconfig/scene/command.h"
#include "reconfig/scene/history.h"
#include "reconfig/scene/reconfigurable.h"
#include "reconfig/scene/scene_file.h"

namespace reconfig::studio {

/// The scene is immutable between edits: every edit makes a new version (a copy with the
/// command applied), hands it to the collision service together with the command's dirty set
/// and keeps it as the current one, so the service's background thread never sees a scene
/// that changes under it.
class Document {
 public:
  using Clock = std::chrono::steady_clock;

  /// Loads a scene file, first removing the temporaries a killed save of it or of its autosave
  /// left behind. @throws InputError naming the file and JSON path of the problem
  /// `options` are the studio's: the design's own collision settings take precedence.
  static std::unique_ptr<Document> open(const std::filesystem::path& file,
                                        collision::CollisionServiceOptions options = {},
                                        const scene::SceneLoadOptions& load = {});
  /// Loads the autosave of `file` instead of the file itself (crash recovery): the document
  /// still saves to `file` and starts out modified. @throws InputError
  static std::unique_ptr<Document> recover(const std::filesystem::path& file,
                                           collision::CollisionServiceOptions options = {},
                                           const scene::SceneLoadOptions& load = {});

  Document(scene::Reconfigurable scene, std::filesystem::path file, collision::CollisionServiceOptions options);

  const scene::Reconfigurable& scene() const { return *scene_; }
  /// The current version itself, for work that outlives the frame (it never changes: an edit
  /// makes a new one).
  std::shared_ptr<const scene::Reconfigurable> shared_scene() const { return scene_; }
  const std::filesystem::path& file() const { return file_; }
  /// Differs from the file as opened or last saved: undoing back to that version is clean
  /// again. A recovered autosave is modified until saved.
  bool modified() const { return saved_step_ != step_; }

  /// Applies `command` as one undoable step. A command the scene refuses (InputError) leaves
  /// everything as it was. @return "" on success, else the reason it was refused
  std::string execute(std::unique_ptr<scene::Command> command);
  bool undo();
  bool redo();
  std::string undo_label() const { return history_.undo_label(); }
  std::string redo_label() const { return history_.redo_label(); }

  /// Writes the scene atomically to its file (or to `file`, which it then belongs to) and
  /// drops the autosave. @throws InputError when the file cannot be written
  void save();
  /// Saves with `view` as the scene's camera. The camera is no edit: it has no undo step, and
  /// looking around does not make the design modified; it is kept whenever the design is saved.
  void save_as(const std::filesystem::path& file, const std::optional<scene::SavedView>& view);

  /// Writes the autosave when the scene changed since the last one and `interval` has passed
  /// since then (or since the first call: `now` is the caller's clock, which may be simulated).
  /// Never throws: a failed autosave is reported in the return value.
  /// @return "" when nothing went wrong
  std::string autosave_if_due(Clock::time_point now, std::chrono::milliseconds interval);
  /// Where the autosave of `file` lives: a hidden file next to it (so relative mesh paths
  /// stay valid), e.g. `dir/.scene.json.autosave`.
  static std::filesystem::path autosave_path(const std::filesystem::path& file);
  /// Where the autosave keeps the meshes of parts edited since the last save (sculpted, for
  /// example), which have no file yet: `dir/.scene.json.autosave-meshes/<part>.obj`.
  static std::filesystem::path autosave_meshes_path(const std::filesystem::path& file);
  /// Whether `file` has an autosave newer than itself (unsaved work from a crash).
  static bool has_recovery(const std::filesystem::path& file);
  /// Throws the unsaved edits away for good (closing with Discard): removes the autosave and
  /// its meshes, so that the next open does not offer to recover them.
  void discard_autosave();

  /// The parts' rest meshes as shared objects (for drawing them GPU-resident): replaced only
  /// when an edit changes a part's geometry or the list of parts, so they outlive edits of
  /// poses and keys.
  const std::vector<std::shared_ptr<const geometry::Mesh>>& part_meshes() const { return part_meshes_; }
  /// Per part: its mesh is closed and outward-oriented (checked when its geometry changes).
  const std::vector<bool>& solid_parts() const { return solid_parts_; }
  /// Per part: a coarser copy for drawing while things move, in designs of more than
  /// `kDetailedTriangles` triangles (the parts share a budget of that many); else the same
  /// objects as `part_meshes`.
  const std::vector<std::shared_ptr<const geometry::Mesh>>& moving_meshes() const { return moving_meshes_; }
  static constexpr int kDetailedTriangles = 20000;

  const collision::CollisionService& collisions() const { return *service_; }
  /// How collisions are detected now: the studio's options with the design's collision
  /// settings. An edit of those (`scene::set_collision_settings`, or undoing one) hands the
  /// design to a new service, which detects every transition again.
  const collision::DetectorOptions& detector_options() const { return service_options_.detector; }
  /// Scene versions an edit replaced stay alive until this is called (at the end of each UI
  /// frame): a panel may hold references into the scene it started drawing from across an edit
  /// it makes.
  void release_retired_scenes() { retired_.clear(); }
  /// The version number of the current scene as submitted to the collision service.
  std::uint64_t version() const { return version_; }

 private:
  void publish(std::shared_ptr<const scene::Reconfigurable> next, const scene::DirtySet& dirty);
  /// Redo (forward) or undo one step on a new version of the scene.
  bool step_history(bool forward);

  std::shared_ptr<const scene::Reconfigurable> scene_;
  std::vector<std::shared_ptr<const scene::Reconfigurable>> retired_;  ///< see `release_retired_scenes`
  std::vector<std::shared_ptr<const geometry::Mesh>> part_meshes_;
  std::vector<bool> solid_parts_;
  std::vector<std::shared_ptr<const geometry::Mesh>> moving_meshes_;
  std::filesystem::path file_;
  scene::History history_;
  collision::CollisionServiceOptions studio_options_;   ///< before the design's settings
  collision::CollisionServiceOptions service_options_;  ///< those of `service_`
  std::unique_ptr<collision::CollisionService> service_;
  std::uint64_t version_ = 0;
  /// Steps of the history applied (edits and redos minus undos), and that count when the file
  /// was last saved (none: the saved version is no longer reachable by undo and redo).
  int step_ = 0;
  std::optional<int> saved_step_ = 0;
  bool autosave_pending_ = false;
  std::optional<Clock::time_point> last_autosave_;  ///< by the caller's clock; none before the first call
};

}  // namespace reconfig::studio
