#include "studio.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <system_error>
#include <thread>
#include <utility>

#include "authoring_menu.h"
#include "collision_settings.h"
#include "counted.h"
#include "inspector_panel.h"
#include "interval_kinds.h"
#include "keys.h"
#include "panel_window.h"
#include "reconfig/common/input_error.h"
#include "reconfig/view/saved_camera.h"
#include "reconfig/view/scene_bounds.h"
#include "reconfig/view/working_side.h"
#include "resolve_panel.h"
#include "state_graph_panel.h"
#include "status_bar.h"
#include "timeline_panel.h"
#include "viewport_panel.h"

namespace reconfig::studio {

namespace fs = std::filesystem;

collision::CollisionServiceOptions editor_collision_options() {
  collision::CollisionServiceOptions options;
  options.max_threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()) - 1);
  options.background_priority = true;
  return options;
}

/// The panels' own state (each panel's header says what it owns), held here so that studio.h
/// does not include their headers: changing one panel recompiles its users only.
struct Studio::Panels {
  TimelinePanel timeline;
  StatusBar status_bar;
  StateGraphPanel state_graph;
  AuthoringMenus authoring;
  CollisionSettingsWindow collision_settings;
  InspectorPanel inspector;
  ResolvePanel resolve;
  ViewportPanel viewport;
};

Studio::Studio(StudioOptions options)
    : options_(std::move(options)), renderer_(render::RendererOptions{0}), panels_(std::make_unique<Panels>()) {}

Studio::~Studio() = default;

TimelinePanel& Studio::timeline() { return panels_->timeline; }
StatusBar& Studio::status_bar() { return panels_->status_bar; }
StateGraphPanel& Studio::state_graph() { return panels_->state_graph; }
AuthoringMenus& Studio::authoring() { return panels_->authoring; }
CollisionSettingsWindow& Studio::collision_settings() { return panels_->collision_settings; }
InspectorPanel& Studio::inspector() { return panels_->inspector; }
ViewportPanel& Studio::viewport() { return panels_->viewport; }
std::optional<Gizmo> Studio::gizmo() const { return panels_->viewport.gizmo(); }
ResolvePanel& Studio::resolve() { return panels_->resolve; }
bool Studio::status_window_open() const { return panels_->status_bar.window_open(); }
void Studio::open_authoring_dialog(AuthoringDialog dialog) { authoring().open(std::move(dialog)); }
const std::optional<AuthoringDialog>& Studio::authoring_dialog() const { return panels_->authoring.dialog(); }
bool Studio::accept_authoring_dialog(const AuthoringDialog& dialog) { return authoring().accept(*this, dialog); }
void Studio::show_collision_settings() { collision_settings().show(*this); }
bool Studio::request_hint() { return resolve().request_hint(*this); }
bool Studio::slide_along_hint(double amount, bool live) { return resolve().slide_along_hint(*this, amount, live); }
bool Studio::start_auto_resolve(bool move_times, bool move_states) {
  return resolve().start_auto_resolve(*this, move_times, move_states);
}
void Studio::cancel_auto_resolve() { resolve().cancel_auto_resolve(*this); }
bool Studio::auto_resolving() const { return panels_->resolve.auto_resolving(); }
bool Studio::hint_pending() const { return panels_->resolve.hint_pending(); }
const std::optional<HintView>& Studio::resolution_hint() const { return panels_->resolve.hint(); }

bool Studio::open(const fs::path& file) {
  if (refuse_while_linkage_unsaved(file)) return false;
  if (is_linkage_file(file)) return linkage_panel_.open_file(*this, file);
  try {
    document_ = Document::open(file, options_.collisions, options_.load);
  } catch (const std::exception& error) {
    std::error_code ignored;
    const bool autosave = fs::is_regular_file(Document::autosave_path(fs::absolute(file)), ignored);
    set_status(fmt::format("cannot open {}: {}{}", file.string(), error.what(),
                           autosave ? " (its autosave can be recovered)" : ""),
               true);
    if (autosave) recovery_candidate_ = fs::absolute(file);
    return autosave;
  }
  reset_view_for_new_document();
  set_status(fmt::format("opened {}", file.string()));
  if (Document::has_recovery(file)) recovery_candidate_ = fs::absolute(file);
  return true;
}

bool Studio::save() {
  if (linkage_panel_.lone()) return linkage_panel_.save(*this);
  if (!document_) return false;
  return save_as(document_->file());
}

bool Studio::save_as(const fs::path& file) {
  if (linkage_panel_.lone()) return linkage_panel_.save(*this, file);
  if (!document_) return false;
  try {
    document_->save_as(file, view::saved_view(camera_));
  } catch (const std::exception& error) {
    set_status(fmt::format("not saved: {}", error.what()), true);
    return false;
  }
  set_status(fmt::format("saved {}", document_->file().string()));
  return true;
}

void Studio::reset_view_for_new_document() {
  open_transitions_.clear();
  active_transition_ = -1;
  active_state_ = 0;
  if (!document_->scene().transitions.empty()) open_transition(0);
  time_ = 0;
  playing_ = false;
  selected_part_ = -1;
  selected_key_.reset();
  viewport().cancel_drags();
  timeline().cancel_drag();
  resolve().reset();  // hints and resolutions belong to the design they were computed for
  // The camera it was saved with, else a view of its working side, framed at the first draw.
  const scene::Reconfigurable& scene = document_->scene();
  frame_pending_ = !scene.view;
  if (scene.view) {
    camera_ = view::camera_from(*scene.view, shown_bounds());
  } else {
    view::aim_at_working_side(camera_, scene);
  }
  linkage_panel_.document_opened(*this);
}

void Studio::set_status(std::string message, bool error) {
  status_ = std::move(message);
  status_is_error_ = error;
  status_bar().message_changed(error);
}

bool Studio::recover_autosave() {
  const fs::path file = std::exchange(recovery_candidate_, {});
  try {
    document_ = Document::recover(file, options_.collisions, options_.load);
  } catch (const std::exception& error) {
    set_status(fmt::format("cannot recover: {}", error.what()), true);
    return false;
  }
  reset_view_for_new_document();
  set_status("recovered the autosave; save to keep it");
  return true;
}

std::shared_ptr<const collision::CollisionSnapshot> Studio::collisions() const {
  return document_ ? document_->collisions().snapshot() : nullptr;
}

std::string Studio::collision_summary() const {
  const auto snapshot = collisions();
  if (!snapshot) return "";
  if (!snapshot->complete || snapshot->version != document_->version()) {
    std::size_t done = 0;
    for (const auto& transition : snapshot->transitions)
      done += transition.up_to_date && snapshot->version == document_->version();
    return fmt::format("collisions: detecting... {} of {} done", done,
                       counted(document_->scene().transitions.size(), "transition"));
  }
  std::size_t count = 0, clearances = 0;
  for (const auto& transition : snapshot->transitions) {
    count += transition.intervals.size();
    clearances += clearance_count(transition.intervals);
  }
  const std::string clearance_text =
      clearances > 0 ? fmt::format(" and {}", counted(clearances, "clearance interval")) : std::string();
  return fmt::format("collisions: {}{} in {}, up to date", counted(count - clearances, "interval"), clearance_text,
                     counted(snapshot->transitions.size(), "transition"));
}

bool Studio::refuse_while_linkage_unsaved(const fs::path& file) {
  if (!linkage_panel_.lone_modified()) return false;
  set_status(fmt::format("{} not opened: the linkage open has unsaved edits; save it (Ctrl+S) or close it first",
                         file.string()),
             true);
  return true;
}

void Studio::request_close() {
  if ((document_ && document_->modified()) || linkage_panel_.lone_modified()) confirm_close_ = true;
  else quit_ = true;
}

void Studio::discard_and_quit() {
  if (document_) document_->discard_autosave();
  quit_ = true;
}

void Studio::frame(std::chrono::steady_clock::time_point now) {
  const double dt = last_frame_ ? std::chrono::duration<double>(now - *last_frame_).count() : 0.0;
  last_frame_ = now;
  now_ = now;
  seconds_ += dt;
  if (camera_glide_) {
    camera_ = camera_glide_->at(seconds_);
    if (camera_glide_->done(seconds_)) camera_glide_.reset();
  }
  if (playing_) advance_playback(dt);
  resolve().update(*this);
  handle_shortcuts();
  draw_menu_bar();
  state_graph().draw(*this);
  inspector().draw(*this);
  viewport().draw(*this);
  timeline().draw(*this);
  linkage_panel_.draw(*this);  // after the timeline: a linkage opened alone covers it
  pip_.update(*this);
  pip_.draw(*this);
  shaping_.update(*this);
  shaping_.draw(*this);
  status_bar().draw(*this);
  draw_modals();
  collision_settings().draw(*this);
  if (document_) {
    std::string problem = document_->autosave_if_due(now, options_.autosave_interval);
    if (!problem.empty()) set_status(std::move(problem), true);
    document_->release_retired_scenes();  // the panels are done with the scenes they drew from
  }
}

void Studio::advance_playback(double seconds) {
  if (active_transition_ < 0) {
    playing_ = false;
    return;
  }
  time_ = std::min(1.0, time_ + seconds * options_.play_speed);
  if (time_ >= 1.0) playing_ = false;
}

void Studio::handle_shortcuts() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return;
  const bool ctrl = io.KeyCtrl, shift = io.KeyShift;
  if (ctrl && ImGui::IsKeyPressed(keys::kZ, false)) {
    if (shift) redo();
    else undo();
  } else if (ctrl && ImGui::IsKeyPressed(keys::kS, false)) {
    save();
  } else if (ctrl && ImGui::IsKeyPressed(keys::kO, false)) {
    show_open_dialog_ = true;
  } else if (!ctrl) {
    if (ImGui::IsKeyPressed(keys::kSpace, false)) toggle_play();
    if (ImGui::IsKeyPressed(keys::kLeft)) step(-1);
    if (ImGui::IsKeyPressed(keys::kRight)) step(1);
    if (ImGui::IsKeyPressed(keys::kI, false)) insert_key();
    if (ImGui::IsKeyPressed(keys::kDelete, false)) delete_selected_key();
    if (ImGui::IsKeyPressed(keys::kF, false)) frame_all();
    if (ImGui::IsKeyPressed(keys::kH, false)) request_hint();
    if (ImGui::IsKeyPressed(keys::kV, false)) jump_to_best_view();
    if (ImGui::IsKeyPressed(keys::kEscape, false)) select_part(-1);
    if (ImGui::IsKeyPressed(keys::kK, false)) sculpt_.set_mode(*this, !sculpt_.mode());
  }
}

// ---- actions ---------------------------------------------------------------------------------

void Studio::open_transition(int transition) {
  if (!document_ || transition < 0 || transition >= static_cast<int>(document_->scene().transitions.size())) return;
  if (std::find(open_transitions_.begin(), open_transitions_.end(), transition) == open_transitions_.end())
    open_transitions_.push_back(transition);
  if (active_transition_ != transition) selected_key_.reset();
  active_transition_ = transition;
}

void Studio::close_transition(int transition) {
  std::erase(open_transitions_, transition);
  if (active_transition_ == transition) {
    active_transition_ = open_transitions_.empty() ? -1 : open_transitions_.back();
    selected_key_.reset();
    if (active_transition_ < 0 && document_) {
      // Keep showing the state the closed transition ended in.
      const int state = document_->scene().find_state(document_->scene().transitions[transition].from);
      active_state_ = std::max(state, 0);
    }
  }
}

void Studio::set_time(double t) { time_ = std::clamp(t, 0.0, 1.0); }

void Studio::step(int frames) {
  playing_ = false;
  set_time(time_ + frames * detector_options().frame);
}

void Studio::toggle_play() {
  if (active_transition_ < 0) return;
  if (!playing_ && time_ >= 1.0) time_ = 0;
  playing_ = !playing_;
}

void Studio::select_part(int part) {
  if (!document_ || part >= static_cast<int>(document_->scene().parts.size())) part = -1;
  if (part != selected_part_) selected_key_.reset();
  selected_part_ = part;
}

std::optional<motion::Pose> Studio::selected_pose() const {
  if (!document_ || selected_part_ < 0) return std::nullopt;
  const scene::Reconfigurable& scene = document_->scene();
  if (active_transition_ >= 0) return scene.pose_at(active_transition_, selected_part_, time_);
  return scene.states[active_state_].pose_of(scene.parts[selected_part_].name);
}

bool Studio::execute(std::unique_ptr<scene::Command> command) {
  if (!document_) return false;
  const std::string label = command->label();
  const ViewNames view = remember_view();
  const std::string refusal = document_->execute(std::move(command));
  restore_view(view);
  if (!refusal.empty()) {
    set_status(fmt::format("{}: refused — {}", label, refusal), true);
    return false;
  }
  set_status(label);
  return true;
}

bool Studio::apply_pose(const motion::Pose& pose) {
  if (!document_ || selected_part_ < 0) return false;
  const scene::Reconfigurable& scene = document_->scene();
  const std::string& part = scene.parts[selected_part_].name;
  if (active_transition_ < 0)
    return execute(scene::set_state_pose(scene.states[active_state_].name, part, pose));
  try {
    return execute(scene::set_pose_at(scene, scene.transitions[active_transition_].name, part, time_, pose));
  } catch (const InputError& error) {
    set_status(error.what(), true);
    return false;
  }
}

bool Studio::insert_key() {
  if (active_transition_ < 0 || time_ <= 0 || time_ >= 1) {
    set_status("keys are inserted at an inner time of an open transition", true);
    return false;
  }
  const auto pose = selected_pose();
  if (!pose) {
    set_status("select a part to key it", true);
    return false;
  }
  return apply_pose(*pose);
}

const scene::KeyframedTrack* Studio::selected_keyframed_track() const {
  if (!document_ || active_transition_ < 0 || selected_part_ < 0) return nullptr;
  return document_->scene().keyframed_track(active_transition_, selected_part_);
}

bool Studio::delete_selected_key() {
  if (!document_ || !selected_key_ || active_transition_ < 0 || selected_part_ < 0) return false;
  const scene::Reconfigurable& scene = document_->scene();
  const bool done = execute(scene::remove_key(scene.transitions[active_transition_].name,
                                              scene.parts[selected_part_].name, selected_key_->kind,
                                              selected_key_->index));
  if (done) selected_key_.reset();
  return done;
}

bool Studio::move_key_time(KeyRef key, double t) {
  if (!document_ || active_transition_ < 0 || selected_part_ < 0) return false;
  const scene::Reconfigurable& scene = document_->scene();
  const scene::KeyframedTrack* track = selected_keyframed_track();
  if (!track) return false;
  const std::string& transition = scene.transitions[active_transition_].name;
  const std::string& part = scene.parts[selected_part_].name;
  if (key.kind == scene::KeyKind::kTranslation) {
    if (key.index < 0 || key.index >= static_cast<int>(track->translation.size())) return false;
    motion::TranslationKey value = track->translation[key.index];
    value.time = t;
    return execute(scene::set_translation_key(transition, part, key.index, value));
  }
  if (key.index < 0 || key.index >= static_cast<int>(track->rotation.size())) return false;
  motion::RotationKey value = track->rotation[key.index];
  value.time = t;
  return execute(scene::set_rotation_key(transition, part, key.index, value));
}

bool Studio::undo() { return step_history(false); }
bool Studio::redo() { return step_history(true); }

bool Studio::step_history(bool forward) {
  if (linkage_panel_.lone()) return forward ? linkage_panel_.redo(*this) : linkage_panel_.undo(*this);
  if (!document_) return false;
  const std::string label = forward ? document_->redo_label() : document_->undo_label();
  const ViewNames view = remember_view();
  const bool stepped = forward ? document_->redo() : document_->undo();
  restore_view(view);
  if (!stepped) {
    set_status(forward ? "nothing to redo" : "nothing to undo");
    return false;
  }
  selected_key_.reset();
  set_status((forward ? "redid " : "undid ") + label);
  return true;
}

Eigen::AlignedBox3d Studio::shown_bounds() const {
  const scene::Reconfigurable& scene = document_->scene();
  // The whole motion, not only the current instant, so nothing leaves the view when playing.
  if (active_transition_ >= 0) return view::scene_bounds_over(scene, active_transition_, 9);
  return view::scene_bounds_in_state(scene, active_state_);
}

void Studio::frame_all() {
  if (!document_) return;
  const ImVec2 size{layout_.viewport_max.x - layout_.viewport_min.x, layout_.viewport_max.y - layout_.viewport_min.y};
  const double aspect = size.y > 0 ? size.x / size.y : 1.5;
  camera_.frame_all(shown_bounds(), aspect);
  frame_pending_ = false;
}

// ---- layout queries --------------------------------------------------------------------------

ImVec2 Studio::timeline_point(double t) const {
  return {static_cast<float>(layout_.scrub_min.x + t * (layout_.scrub_max.x - layout_.scrub_min.x)),
          (layout_.scrub_min.y + layout_.scrub_max.y) / 2};
}

std::optional<ImVec2> Studio::viewport_point(const Eigen::Vector3d& world) const {
  const int width = static_cast<int>(layout_.viewport_max.x - layout_.viewport_min.x);
  const int height = static_cast<int>(layout_.viewport_max.y - layout_.viewport_min.y);
  if (width <= 0 || height <= 0) return std::nullopt;
  const auto projected = view::project_to_pixel(camera_, width, height, world);
  if (!projected) return std::nullopt;
  return ImVec2{layout_.viewport_min.x + static_cast<float>(projected->pixel.x()),
                layout_.viewport_min.y + static_cast<float>(projected->pixel.y())};
}

// ---- dialogs -------------------------------------------------------------------------------

void Studio::draw_modals() {
  if (!recovery_candidate_.empty()) ImGui::OpenPopup("Recover unsaved work?");
  if (ImGui::BeginPopupModal("Recover unsaved work?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    if (document_ && document_->file() == recovery_candidate_)
      ImGui::Text("%s has an autosave newer than the file:\nthe studio closed before it was saved.",
                  recovery_candidate_.filename().string().c_str());
    else
      ImGui::Text("%s cannot be opened, but it has an autosave:\nrecover the work saved there?",
                  recovery_candidate_.filename().string().c_str());
    if (ImGui::Button("Recover")) {
      recover_autosave();
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard")) {
      std::error_code ignored;
      fs::remove(Document::autosave_path(recovery_candidate_), ignored);
      recovery_candidate_.clear();
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }

  const auto path_dialog = [&](const char* title, bool& show, std::string& path, auto&& accept) {
    if (show) ImGui::OpenPopup(title);
    show = false;
    if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    char buffer[1024];
    std::snprintf(buffer, sizeof buffer, "%s", path.c_str());
    ImGui::SetNextItemWidth(480);
    const bool entered = ImGui::InputText("##path", buffer, sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue);
    path = buffer;
    if (entered || ImGui::Button("OK")) {
      accept(path);
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  };
  path_dialog("Open scene", show_open_dialog_, open_path_input_, [&](const std::string& path) { open(path); });
  path_dialog("Save scene as", show_save_as_dialog_, save_path_input_,
              [&](const std::string& path) { save_as(path); });

  authoring().draw_dialog(*this);
  if (confirm_close_) ImGui::OpenPopup("Save changes?");
  confirm_close_ = false;
  if (ImGui::BeginPopupModal("Save changes?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::TextUnformatted(linkage_panel_.lone_modified() ? "The linkage has unsaved changes."
                                                          : "The design has unsaved changes.");
    if (ImGui::Button("Save")) {
      if (save()) quit_ = true;
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard")) {
      discard_and_quit();
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
}

}  // namespace reconfig::studio
