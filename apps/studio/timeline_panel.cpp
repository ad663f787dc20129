// The timeline of the open transitions: tabs, the scrub strip, collision bands (faint previews
// while detection is coarse, then solid), and the selected part's keys (translation and
// rotation rows) that can be selected, dragged in time, inserted and removed.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "fit_text.h"
#include "keys.h"
#include "panel_window.h"
#include "studio.h"

namespace reconfig::studio {
namespace {

constexpr float kLabelWidth = 96;  ///< the row labels' column, at least; wider for long part names
constexpr float kRowHeight = 20;
constexpr float kDiamond = 6;

void diamond(ImDrawList* draw, ImVec2 center, ImU32 fill, ImU32 outline) {
  const ImVec2 top{center.x, center.y - kDiamond}, right{center.x + kDiamond, center.y},
      bottom{center.x, center.y + kDiamond}, left{center.x - kDiamond, center.y};
  draw->AddQuadFilled(top, right, bottom, left, fill);
  draw->AddQuad(top, right, bottom, left, outline, 1.5f);
}

}  // namespace

void Studio::draw_timeline() {
  const PanelRects rects = current_panel_rects();
  begin_panel("Timeline", rects.timeline_pos, rects.timeline_size);
  if (!document_ || open_transitions_.empty()) {
    ImGui::TextUnformatted(document_ ? "Click an edge of the state graph to open its transition."
                                     : "No design open.");
    ImGui::End();
    return;
  }
  const scene::Reconfigurable& scene = document_->scene();

  // Tabs: one per open transition.
  int close = -1;
  if (ImGui::BeginTabBar("##transitions", ImGuiTabBarFlags_AutoSelectNewTabs)) {
    for (const int transition : open_transitions_) {
      bool keep = true;
      const ImGuiTabItemFlags flags = transition == active_transition_ ? ImGuiTabItemFlags_SetSelected : 0;
      if (ImGui::BeginTabItem(scene.transitions[transition].name.c_str(), &keep, flags)) {
        if (ImGui::IsItemClicked()) open_transition(transition);
        ImGui::EndTabItem();
      } else if (ImGui::IsItemClicked()) {
        open_transition(transition);
      }
      if (!keep) close = transition;
    }
    ImGui::EndTabBar();
  }
  if (close >= 0) close_transition(close);
  if (active_transition_ < 0) {
    ImGui::End();
    return;
  }

  if (ImGui::Button(playing_ ? "Pause" : "Play")) toggle_play();
  ImGui::SameLine();
  float t = static_cast<float>(time_);
  ImGui::SetNextItemWidth(140);
  if (ImGui::SliderFloat("t", &t, 0.0f, 1.0f, "%.3f")) set_time(t);
  ImGui::SameLine();
  ImGui::Checkbox("ghosts", &show_ghosts);
  ImGui::SameLine();
  ImGui::Checkbox("collision boxes", &show_intervals);
  ImGui::SameLine();
  if (ImGui::Button("Best view (V)")) jump_to_best_view();
  ImGui::SameLine();
  ImGui::TextDisabled("Space play   Left/Right step   I key   Del remove key");

  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 cursor = ImGui::GetCursorScreenPos();
  // Wide enough for "move  <part>" of the longest part name (the same whichever part is
  // selected, so the strip does not shift), up to a quarter of the panel.
  float label_width = kLabelWidth;
  for (const scene::Part& part : scene.parts)
    label_width = std::max(label_width, ImGui::CalcTextSize(("move  " + part.name).c_str()).x + 8);
  label_width = std::min(label_width, std::max(kLabelWidth, ImGui::GetContentRegionAvail().x / 4));
  const float width = std::max(ImGui::GetContentRegionAvail().x - label_width - 8, 50.0f);
  const float x0 = cursor.x + label_width, x1 = x0 + width;
  const auto x_of = [&](double time) { return static_cast<float>(x0 + time * (x1 - x0)); };
  const auto t_of = [&](float x) { return std::clamp(static_cast<double>((x - x0) / (x1 - x0)), 0.0, 1.0); };
  const ImGuiIO& io = ImGui::GetIO();

  // Row geometry.
  const float scrub_y = cursor.y, bands_y = scrub_y + kRowHeight + 2;
  const float translation_y = bands_y + kRowHeight + 2, rotation_y = translation_y + kRowHeight + 2;
  layout_.scrub_min = {x0, scrub_y};
  layout_.scrub_max = {x1, scrub_y + kRowHeight};
  layout_.bands_row_y = bands_y + kRowHeight / 2;
  layout_.translation_row_y = translation_y + kRowHeight / 2;
  layout_.rotation_row_y = rotation_y + kRowHeight / 2;

  const ImU32 label = IM_COL32(70, 70, 80, 255);
  draw->AddText({cursor.x, scrub_y + 3}, label, "time");
  draw->AddText({cursor.x, bands_y + 3}, label, "collisions");
  const std::string move_label = selected_part_ >= 0 ? "move  " + scene.parts[selected_part_].name : "move";
  draw->AddText({cursor.x, translation_y + 3}, label, fit_text(move_label, label_width - 4).c_str());
  draw->AddText({cursor.x, rotation_y + 3}, label, "rotate");

  // Scrub strip with ticks every 0.1.
  draw->AddRectFilled({x0, scrub_y}, {x1, scrub_y + kRowHeight}, IM_COL32(225, 225, 232, 255));
  for (int i = 0; i <= 10; ++i) {
    const float x = x_of(i / 10.0);
    draw->AddLine({x, scrub_y + kRowHeight - 6}, {x, scrub_y + kRowHeight}, IM_COL32(110, 110, 120, 255));
    // Right of its tick, but the last one (1.0) left of it, inside the strip, not cut to "1.".
    const std::string tick = fmt::format("{:.1f}", i / 10.0);
    const float text_x = i < 10 ? x + 2 : x - ImGui::CalcTextSize(tick.c_str()).x - 2;
    draw->AddText({text_x, scrub_y + 1}, IM_COL32(110, 110, 120, 255), tick.c_str());
  }
  ImGui::SetCursorScreenPos({x0, scrub_y});
  ImGui::InvisibleButton("##scrub", {width, kRowHeight});
  scrubbing_ = ImGui::IsItemActive();
  if (scrubbing_) {
    playing_ = false;
    set_time(t_of(io.MousePos.x));
  }

  // Collision bands.
  draw->AddRectFilled({x0, bands_y}, {x1, bands_y + kRowHeight}, IM_COL32(240, 240, 244, 255));
  const auto snapshot = collisions();
  const collision::TransitionSnapshot* current = nullptr;
  if (snapshot)
    for (const auto& transition : snapshot->transitions)
      if (transition.transition == active_transition_) current = &transition;
  std::vector<std::pair<double, double>> bands;
  if (current) {
    for (const auto& [a, b] : current->preview)
      draw->AddRectFilled({x_of(a), bands_y + 3}, {std::max(x_of(b), x_of(a) + 2), bands_y + kRowHeight - 3},
                          IM_COL32(240, 150, 60, 70));
    const bool solid = current->up_to_date && snapshot->version == document_->version();
    for (const auto& interval : current->intervals) {
      const ImU32 color = interval.clearance  ? IM_COL32(255, 191, 0, solid ? 230 : 110)  // amber
                          : interval.possible ? IM_COL32(235, 160, 40, solid ? 230 : 110)
                                              : IM_COL32(215, 40, 30, solid ? 230 : 110);
      draw->AddRectFilled({x_of(interval.t0), bands_y + 2},
                          {std::max(x_of(interval.t1), x_of(interval.t0) + 2), bands_y + kRowHeight - 2}, color, 3);
      bands.emplace_back(interval.t0, interval.t1);
    }
  }
  ImGui::SetCursorScreenPos({x0, bands_y});
  ImGui::InvisibleButton("##bands", {width, kRowHeight});
  if (ImGui::IsItemClicked()) {
    const double at = t_of(io.MousePos.x), slack = 4.0 / width;
    for (const auto& [a, b] : bands)
      if (at >= a - slack && at <= b + slack) {
        playing_ = false;
        set_time(a);
        break;
      }
  }
  if (ImGui::IsItemHovered() && current)
    for (const auto& interval : current->intervals)
      if (std::abs(t_of(io.MousePos.x) - std::clamp(t_of(io.MousePos.x), interval.t0, interval.t1)) < 4.0 / width) {
        std::string parts;
        for (const int part : interval.parts) parts += (parts.empty() ? "" : " × ") + scene.parts[part].name;
        ImGui::SetTooltip("%s\nt = %.3f to %.3f%s\nP: show it in the picture-in-picture", parts.c_str(),
                          interval.t0, interval.t1,
                          interval.clearance  ? "\n(clearance: closer than allowed, not colliding)"
                          : interval.possible ? "\n(possible: near miss of the proxies)"
                                              : "");
        if (ImGui::IsKeyPressed(keys::kP, false)) pip_.open_on(*this, active_transition_, interval);
      }
  pip_.draw_timeline_marker(draw, *this);

  // Keys of the selected part.
  for (const float y : {translation_y, rotation_y})
    draw->AddRectFilled({x0, y}, {x1, y + kRowHeight}, IM_COL32(236, 236, 240, 255));
  const scene::KeyframedTrack* track = nullptr;
  if (selected_part_ >= 0) {
    const scene::Transition& transition = scene.transitions[active_transition_];
    const auto it = transition.tracks.find(scene.parts[selected_part_].name);
    if (it != transition.tracks.end()) track = std::get_if<scene::KeyframedTrack>(&it->second);
    // Screw-pose tracks (and parts a linkage drives) show their poses, not draggable keys.
    if (it != transition.tracks.end() && !track) {
      const bool driven = transition.linkage && transition.linkage->drives(it->first);
      for (const double time : scene::key_times(it->second))
        for (const float y : {translation_y, rotation_y})
          draw->AddCircleFilled({x_of(time), y + kRowHeight / 2}, 2.5f, IM_COL32(120, 90, 160, 255));
      draw->AddText({x0 + 4, rotation_y + 3}, IM_COL32(90, 70, 130, 255),
                    driven ? "driven by the transition's linkage" : "screw poses");
    }
  }
  const auto key_times = [&](scene::KeyKind kind) {
    std::vector<double> times;
    if (!track) return times;
    if (kind == scene::KeyKind::kTranslation)
      for (const auto& key : track->translation) times.push_back(key.time);
    else
      for (const auto& key : track->rotation) times.push_back(key.time);
    return times;
  };
  for (const scene::KeyKind kind : {scene::KeyKind::kTranslation, scene::KeyKind::kRotation}) {
    const float y = kind == scene::KeyKind::kTranslation ? translation_y : rotation_y;
    const std::vector<double> times = key_times(kind);
    ImGui::SetCursorScreenPos({x0 - kDiamond, y});
    ImGui::InvisibleButton(kind == scene::KeyKind::kTranslation ? "##translation-keys" : "##rotation-keys",
                           {width + 2 * kDiamond, kRowHeight});
    if (ImGui::IsItemClicked()) {
      // Select the diamond under the mouse (and start dragging it), or move the playhead.
      int hit = -1;
      for (int i = 0; i < static_cast<int>(times.size()); ++i)
        if (std::abs(x_of(times[i]) - io.MousePos.x) <= kDiamond + 1) hit = i;
      if (hit >= 0) {
        selected_key_ = KeyRef{kind, hit};
        key_drag_ = selected_key_;
        key_drag_time_ = times[hit];
      } else {
        selected_key_.reset();
        set_time(t_of(io.MousePos.x));
      }
    }
    if (key_drag_ && key_drag_->kind == kind) {
      if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        key_drag_time_ = t_of(io.MousePos.x);
      } else {
        const KeyRef key = *key_drag_;
        key_drag_.reset();
        if (io.MouseDragMaxDistanceSqr[0] > 4 && key.index < static_cast<int>(times.size()) &&
            key_drag_time_ != times[key.index])
          move_key_time(key, key_drag_time_);
      }
    }
    for (int i = 0; i < static_cast<int>(times.size()); ++i) {
      const bool selected = selected_key_ && *selected_key_ == KeyRef{kind, i};
      const bool dragged = key_drag_ && *key_drag_ == KeyRef{kind, i};
      const double at = dragged ? key_drag_time_ : times[i];
      diamond(draw, {x_of(at), y + kRowHeight / 2},
              selected ? IM_COL32(250, 200, 30, 255) : IM_COL32(90, 110, 170, 255), IM_COL32(30, 30, 40, 255));
    }
  }

  // Playhead over every row.
  const float x = x_of(time_);
  draw->AddLine({x, scrub_y}, {x, rotation_y + kRowHeight}, IM_COL32(30, 90, 220, 255), 2);
  draw->AddTriangleFilled({x - 6, scrub_y}, {x + 6, scrub_y}, {x, scrub_y + 8}, IM_COL32(30, 90, 220, 255));
  draw_time_hints(draw);
  ImGui::End();
}

}  // namespace reconfig::studio
