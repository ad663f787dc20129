#include "document.h"

#include <system_error>

#include "reconfig/common/input_error.h"
#include "reconfig/common/write_atomically.h"
#include "reconfig/scene/scene_file.h"

namespace reconfig::studio {

namespace fs = std::filesystem;

std::unique_ptr<Document> Document::open(const fs::path& file, collision::CollisionServiceOptions options) {
  return std::make_unique<Document>(scene::load_scene(file), fs::absolute(file), options);
}

std::unique_ptr<Document> Document::recover(const fs::path& file, collision::CollisionServiceOptions options) {
  const fs::path autosave = autosave_path(fs::absolute(file));
  auto document = std::make_unique<Document>(scene::load_scene(autosave), fs::absolute(file), options);
  document->modified_ = true;
  return document;
}

Document::Document(scene::Reconfigurable scene, fs::path file, collision::CollisionServiceOptions options)
    : file_(std::move(file)), service_(std::make_unique<collision::CollisionService>(options)) {
  scene::DirtySet everything;
  everything.structure_changed = true;
  publish(std::make_shared<const scene::Reconfigurable>(std::move(scene)), everything);
}

void Document::publish(std::shared_ptr<const scene::Reconfigurable> next, const scene::DirtySet& dirty) {
  scene_ = std::move(next);
  const auto share = [&](int part) { return std::make_shared<const geometry::Mesh>(scene_->parts[part].mesh); };
  if (dirty.structure_changed || part_meshes_.size() != scene_->parts.size()) {
    part_meshes_.clear();
    for (int part = 0; part < static_cast<int>(scene_->parts.size()); ++part) part_meshes_.push_back(share(part));
  } else {
    for (const int part : dirty.geometry_changed) part_meshes_[part] = share(part);
  }
  version_ = service_->submit(scene_, dirty);
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
  modified_ = autosave_pending_ = true;
  return "";
}

bool Document::undo() {
  if (!history_.can_undo()) return false;
  auto next = std::make_shared<scene::Reconfigurable>(*scene_);
  const scene::DirtySet dirty = history_.undo(*next);
  publish(std::move(next), dirty);
  modified_ = autosave_pending_ = true;
  return true;
}

bool Document::redo() {
  if (!history_.can_redo()) return false;
  auto next = std::make_shared<scene::Reconfigurable>(*scene_);
  const scene::DirtySet dirty = history_.redo(*next);
  publish(std::move(next), dirty);
  modified_ = autosave_pending_ = true;
  return true;
}

void Document::save() { save_as(file_); }

void Document::save_as(const fs::path& file) {
  // Saving may turn edited geometry into mesh files: that is a new version of the scene.
  auto next = std::make_shared<scene::Reconfigurable>(*scene_);
  scene::save_scene(*next, file);
  scene_ = std::move(next);
  file_ = fs::absolute(file);
  modified_ = autosave_pending_ = false;
  std::error_code ignored;
  fs::remove(autosave_path(file_), ignored);
}

std::string Document::autosave_if_due(Clock::time_point now, std::chrono::milliseconds interval) {
  if (!autosave_pending_ || now - last_autosave_ < interval) return "";
  last_autosave_ = now;
  autosave_pending_ = false;
  try {
    const std::string json = scene::scene_to_json(*scene_, file_.parent_path());
    write_atomically(autosave_path(file_), [&](std::ostream& out) { out << json; });
  } catch (const std::exception& error) {
    return std::string("autosave failed: ") + error.what();
  }
  return "";
}

fs::path Document::autosave_path(const fs::path& file) {
  return file.parent_path() / ("." + file.filename().string() + ".autosave");
}

bool Document::has_recovery(const fs::path& file) {
  std::error_code error;
  const fs::path autosave = autosave_path(fs::absolute(file));
  if (!fs::exists(autosave, error)) return false;
  if (!fs::exists(file, error)) return true;
  return fs::last_write_time(autosave, error) >= fs::last_write_time(file, error);
}

}  // namespace reconfig::studio
