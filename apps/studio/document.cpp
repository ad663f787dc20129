#include "document.h"

#include <system_error>
#include <variant>

#include "reconfig/collision/detector_settings.h"
#include "reconfig/common/input_error.h"
#include "reconfig/common/write_atomically.h"
#include "reconfig/geometry/display_simplification.h"
#include "reconfig/geometry/mesh_check.h"
#include "reconfig/scene/scene_file.h"

namespace reconfig::studio {

namespace fs = std::filesystem;

namespace {

/// The studio always shows the design in one of its states (or a transition between two):
/// a design without states is refused with a message rather than opened.
scene::Reconfigurable with_a_state(scene::Reconfigurable scene, const fs::path& file) {
  if (scene.states.empty())
    throw InputError(file.string(), "states",
                     "the design has no states; the studio shows a design in one of its states "
                     "(add one, e.g. \"states\": [{\"name\": \"rest\"}])");
  return scene;
}

}  // namespace

std::unique_ptr<Document> Document::open(const fs::path& file, collision::CollisionServiceOptions options,
                                         const scene::SceneLoadOptions& load) {
  // What a save or an autosave killed midway left behind (it would stay forever otherwise).
  remove_stale_temporary(file);
  remove_stale_temporary(autosave_path(fs::absolute(file)));
  return std::make_unique<Document>(with_a_state(scene::load_scene(file, load), file), fs::absolute(file), options);
}

std::unique_ptr<Document> Document::recover(const fs::path& file, collision::CollisionServiceOptions options,
                                            const scene::SceneLoadOptions& load) {
  const fs::path autosave = autosave_path(fs::absolute(file));
  scene::Reconfigurable scene = with_a_state(scene::load_scene(autosave, load), autosave);
  // Meshes the autosave kept for edited parts are still edits: the next save writes them
  // beside the design, and discarding the autosave may remove their folder.
  const fs::path meshes = fs::weakly_canonical(autosave_meshes_path(fs::absolute(file)));
  for (scene::Part& part : scene.parts)
    if (const auto* mesh = std::get_if<scene::MeshFile>(&part.source);
        mesh && fs::weakly_canonical(mesh->path).parent_path() == meshes)
      part.source = scene::EditedMesh{};
  auto document = std::make_unique<Document>(std::move(scene), fs::absolute(file), options);
  document->saved_step_.reset();
  return document;
}

Document::Document(scene::Reconfigurable scene, fs::path file, collision::CollisionServiceOptions options)
    : file_(std::move(file)), studio_options_(std::move(options)) {
  scene::DirtySet everything;
  everything.structure_changed = true;
  publish(std::make_shared<const scene::Reconfigurable>(std::move(scene)), everything);
}

void Document::publish(std::shared_ptr<const scene::Reconfigurable> next, const scene::DirtySet& dirty) {
  if (scene_) retired_.push_back(std::move(scene_));
  scene_ = std::move(next);
  const auto share = [&](int part) {
    part_meshes_[part] = std::make_shared<const geometry::Mesh>(scene_->parts[part].mesh);
    geometry::MeshCheckOptions quick;
    quick.check_self_intersections = false;
    const geometry::MeshReport report = geometry::check_mesh(*part_meshes_[part], quick);
    solid_parts_[part] = report.is_closed() && report.is_oriented() && report.is_outward();
  };
  const bool everything = dirty.structure_changed || part_meshes_.size() != scene_->parts.size();
  if (everything) {
    part_meshes_.assign(scene_->parts.size(), nullptr);
    solid_parts_.assign(scene_->parts.size(), false);
    for (int part = 0; part < static_cast<int>(scene_->parts.size()); ++part) share(part);
  } else {
    for (const int part : dirty.geometry_changed) share(part);
  }
  if (everything || !dirty.geometry_changed.empty()) {
    // Big designs get coarser copies to draw while things move, each part its share of the budget.
    long total = 0;
    for (const auto& mesh : part_meshes_) total += mesh->F.rows();
    moving_meshes_ = part_meshes_;
    if (total > kDetailedTriangles)
      for (std::size_t part = 0; part < part_meshes_.size(); ++part) {
        const int budget = std::max(200, static_cast<int>(kDetailedTriangles * part_meshes_[part]->F.rows() / total));
        moving_meshes_[part] =
            std::make_shared<const geometry::Mesh>(geometry::simplify_for_display(*part_meshes_[part], budget));
      }
  }
  collision::CollisionServiceOptions wanted = studio_options_;
  wanted.detector = collision::with_settings(studio_options_.detector, scene_->collision);
  if (service_ && collision::settings_of(wanted.detector) == collision::settings_of(service_options_.detector)) {
    version_ = service_->submit(scene_, dirty);
    return;
  }
  // First, or with other settings: a new service detects every transition (the old one's work
  // is abandoned).
  service_options_ = wanted;
  service_ = std::make_unique<collision::CollisionService>(wanted);
  scene::DirtySet all;
  all.structure_changed = true;
  version_ = service_->submit(scene_, all);
}

std::string Document::execute(std::unique_ptr<scene::Command> command) {
  auto next = std::make_shared<scene::Reconfigurable>(*scene_);
  scene::DirtySet dirty;
  try {
    dirty = history_.execute(*next, std::move(command));
  } catch (const InputError& error) {
    return error.what();
  }
  publish(std::move(next), dirty);
  if (saved_step_ > step_) saved_step_.reset();  // the saved version was undone and is now replaced
  ++step_;
  autosave_pending_ = true;
  return "";
}

bool Document::undo() { return step_history(false); }
bool Document::redo() { return step_history(true); }

bool Document::step_history(bool forward) {
  if (forward ? !history_.can_redo() : !history_.can_undo()) return false;
  auto next = std::make_shared<scene::Reconfigurable>(*scene_);
  const scene::DirtySet dirty = forward ? history_.redo(*next) : history_.undo(*next);
  publish(std::move(next), dirty);
  step_ += forward ? 1 : -1;
  autosave_pending_ = modified();
  if (!modified()) discard_autosave();  // back to the saved version: nothing to recover
  return true;
}

void Document::save() { save_as(file_, scene_->view); }

void Document::save_as(const fs::path& file, const std::optional<scene::SavedView>& view) {
  // Saving may turn edited geometry into mesh files: that is a new version of the scene.
  auto next = std::make_shared<scene::Reconfigurable>(*scene_);
  next->view = view;
  scene::save_scene(*next, file);
  scene_ = std::move(next);
  file_ = fs::absolute(file);
  saved_step_ = step_;
  discard_autosave();
}

void Document::discard_autosave() {
  autosave_pending_ = false;
  std::error_code ignored;
  fs::remove(autosave_path(file_), ignored);
  fs::remove_all(autosave_meshes_path(file_), ignored);
}

std::string Document::autosave_if_due(Clock::time_point now, std::chrono::milliseconds interval) {
  if (!last_autosave_) last_autosave_ = now;
  if (!autosave_pending_ || now - *last_autosave_ < interval) return "";
  last_autosave_ = now;
  autosave_pending_ = false;
  try {
    // Edited parts have no mesh file yet: the autosave keeps theirs in its own folder.
    scene::Reconfigurable saved = *scene_;
    scene::write_edited_meshes(saved, autosave_meshes_path(file_));
    const std::string json = scene::scene_to_json(saved, file_.parent_path());
    write_atomically(autosave_path(file_), [&](std::ostream& out) { out << json; });
  } catch (const std::exception& error) {
    return std::string("autosave failed: ") + error.what();
  }
  return "";
}

fs::path Document::autosave_path(const fs::path& file) {
  // Appended, not `"." + …`: GCC 12 warns (-Wrestrict) about the insertion at the front that
  // `const char* + std::string&&` may do, a false positive (GCC bug 105651).
  return file.parent_path() / std::string(".").append(file.filename().string()).append(".autosave");
}

fs::path Document::autosave_meshes_path(const fs::path& file) {
  return file.parent_path() / std::string(".").append(file.filename().string()).append(".autosave-meshes");
}

bool Document::has_recovery(const fs::path& file) {
  std::error_code error;
  const fs::path autosave = autosave_path(fs::absolute(file));
  if (!fs::exists(autosave, error)) return false;
  if (!fs::exists(file, error)) return true;
  return fs::last_write_time(autosave, error) >= fs::last_write_time(file, error);
}

}  // namespace reconfig::studio
