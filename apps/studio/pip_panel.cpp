#include "pip_panel.h"

#include <fmt/format.h>

#include <cmath>

#include "side_effects.h"
#include "studio.h"

namespace reconfig::studio {
namespace {

const collision::TransitionSnapshot* transition_snapshot(const collision::CollisionSnapshot& snapshot, int transition) {
  for (const collision::TransitionSnapshot& t : snapshot.transitions)
    if (t.transition == transition) return &t;
  return nullptr;
}

std::string part_names(const scene::Reconfigurable& scene, const collision::CollisionInterval& interval) {
  std::string names;
  for (int part : interval.parts) names += (names.empty() ? "" : " × ") + scene.parts[part].name;
  return names;
}

}  // namespace

void PipPanel::open_on(Studio& studio, int transition, const collision::CollisionInterval& interval) {
  if (!search_) search_ = std::make_unique<ViewSearch>();
  const std::uint64_t id =
      search_->submit({studio.document()->shared_scene(), transition, interval, studio.camera().fov_y});
  pending_ = Pending{id, transition, interval};
  error_.clear();
}

void PipPanel::close() {
  target_.reset();
  error_.clear();
  pending_.reset();
  if (search_) search_->cancel();
}

void PipPanel::take_search_result() {
  if (!pending_ || !search_) return;
  std::optional<ViewSearch::Result> found = search_->take();
  if (!found || found->id != pending_->id) return;
  const Pending pending = *pending_;
  pending_.reset();
  if (!found->error.empty()) {
    error_ = found->error;
    return;
  }
  target_ = Target{pending.transition, pending.interval, found->time, found->camera};
  drawn_version_ = 0;
}

void PipPanel::update(Studio& studio) {
  take_search_result();
  const auto snapshot = studio.collisions();
  if (!snapshot || !studio.document()) return;
  const collision::TransitionSnapshot* current = transition_snapshot(*snapshot, studio.active_transition());
  if (!current || !current->up_to_date || snapshot->version != studio.document()->version()) return;
  if (snapshot->version == seen_version_) {
    // No edit since: what is worked on is what the designer moved the time or selection to.
    if (!worked_on_ || studio.time() != focus_time_ || studio.selected_part() != focus_part_) {
      const int focus = focused_interval(current->intervals, studio.time(), studio.selected_part());
      worked_on_ = focus >= 0 ? std::optional(current->intervals[focus]) : std::nullopt;
      focus_time_ = studio.time();
      focus_part_ = studio.selected_part();
    }
    return;
  }
  const bool first = seen_version_ == 0;  // the design as opened: nothing was edited yet
  seen_version_ = snapshot->version;
  if (first) return;
  const std::optional<collision::CollisionInterval> side_effect = most_critical_side_effect(current->changes, worked_on_);
  if (worked_on_) {  // the edit reshapes the collision worked on: follow it
    std::optional<collision::CollisionInterval> followed;
    for (const collision::CollisionInterval& interval : current->intervals)
      if (same_collision(interval, *worked_on_)) followed = interval;
    worked_on_ = followed;
  }
  if (side_effect) {
    open_on(studio, current->transition, *side_effect);
    return;
  }
  if (!target_ && !pending_) return;
  // What it shows, or will show once found.
  const int shown_transition = pending_ ? pending_->transition : target_->transition;
  const collision::CollisionInterval shown = pending_ ? pending_->interval : target_->interval;
  if (shown_transition != current->transition) return;
  for (const collision::CollisionInterval& interval : current->intervals)
    if (same_collision(interval, shown)) {
      open_on(studio, current->transition, interval);  // it moved: follow it
      return;
    }
  close();  // its collision is gone
}

void PipPanel::swap(Studio& studio) {
  if (!target_) return;
  pending_.reset();
  if (search_) search_->cancel();
  const Target shown = *target_;
  std::optional<Target> main;
  if (worked_on_ && studio.active_transition() >= 0)
    main = Target{studio.active_transition(), *worked_on_, studio.time(), studio.camera()};
  studio.open_transition(shown.transition);
  studio.set_time(shown.time);
  studio.camera() = shown.camera;
  studio.select_part(shown.interval.parts.front());
  worked_on_ = shown.interval;
  focus_time_ = studio.time();
  focus_part_ = studio.selected_part();
  target_ = main;
  drawn_version_ = 0;
}

void PipPanel::draw(Studio& studio) {
  image_min_ = image_max_ = {0, 0};
  if ((!target_ && !pending_ && error_.empty()) || !studio.document()) return;
  const Layout& layout = studio.layout();
  const float margin = 10, caption = ImGui::GetFrameHeight() + 8;
  ImGui::SetNextWindowPos({layout.viewport_max.x - kWidth - margin - 16, layout.viewport_min.y + margin + 20});
  ImGui::SetNextWindowSize({kWidth + 16, kHeight + caption + 12});
  bool open = true;
  const std::string title =
      target_ ? fmt::format("Side effect: {}  t = {:.3f}###pip", part_names(studio.document()->scene(), target_->interval),
                            target_->time)
      : pending_ ? fmt::format("Side effect: {}  (finding its view)###pip",
                               part_names(studio.document()->scene(), pending_->interval))
                 : std::string("Side effect: no view###pip");
  if (ImGui::Begin(title.c_str(), &open,
                   ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                       ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoScrollbar)) {
    if (target_ && drawn_version_ != studio.document()->version()) {
      studio.render_view(image_, target_->camera, target_->transition, target_->time, {target_->interval.box}, kWidth,
                         kHeight);
      drawn_version_ = studio.document()->version();
    }
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("##pip_image", {kWidth, kHeight});
    const bool clicked = ImGui::IsItemClicked();
    if (target_ && ImGui::IsItemHovered()) ImGui::SetTooltip("Click: swap with the main view");
    const ImVec2 image_max{origin.x + kWidth, origin.y + kHeight};
    ImDrawList* draw = ImGui::GetWindowDrawList();
    if (target_) {
      image_min_ = origin;
      image_max_ = image_max;
      draw->AddImage(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(image_.texture())), image_min_, image_max_,
                     {0, 1}, {1, 0});
    }
    draw->AddRect(origin, image_max, IM_COL32(235, 190, 20, 255), 0, 0, 2);
    if (!target_ && !pending_)
      draw->AddText(nullptr, 0, {origin.x + 8, origin.y + 8}, ImGui::GetColorU32(ImGuiCol_Text), error_.c_str(), nullptr,
                    kWidth - 16);
    if (pending_) {  // in the middle while there is nothing to show, else in a corner
      if (target_) draw_spinner(draw, {image_max.x - 18, origin.y + 18}, 9);
      else draw_spinner(draw, {origin.x + kWidth / 2.0f, origin.y + kHeight / 2.0f}, 18);
    }
    if (clicked) swap(studio);
  }
  ImGui::End();
  if (!open) close();
}

// A three-quarter circle turning once a second.
void PipPanel::draw_spinner(ImDrawList* draw, ImVec2 center, float radius) const {
  const float start = static_cast<float>(std::fmod(ImGui::GetTime(), 1.0) * 2 * M_PI);
  draw->PathArcTo(center, radius, start, start + 1.5f * static_cast<float>(M_PI), 24);
  draw->PathStroke(IM_COL32(235, 190, 20, 255), 0, 3);
}

void PipPanel::draw_timeline_marker(ImDrawList* draw, const Studio& studio) const {
  if (!target_ || target_->transition != studio.active_transition()) return;
  const ImVec2 at = studio.timeline_point(target_->time);
  const Layout& layout = studio.layout();
  draw->AddLine({at.x, layout.scrub_min.y}, {at.x, layout.scrub_max.y}, IM_COL32(240, 190, 0, 255), 3);
  draw->AddTriangleFilled({at.x - 5, layout.scrub_min.y}, {at.x + 5, layout.scrub_min.y}, {at.x, layout.scrub_min.y + 6},
                          IM_COL32(240, 190, 0, 255));
}

}  // namespace reconfig::studio
