#include "timeline_panel.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "fit_text.h"
#include "keys.h"
#include "panel_window.h"
#include "pip_panel.h"
#include "resolve_panel.h"

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

double TimelinePanel::Strip::t_of(float x) const {
  return std::clamp(static_cast<double>((x - x0) / (x1 - x0)), 0.0, 1.0);
}

void TimelinePanel::draw(Studio& studio) {
  const PanelRects rects = current_panel_rects();
  begin_panel("Timeline", rects.timeline_pos, rects.timeline_size);
  if (!studio.document_ || studio.open_transitions_.empty()) {
    ImGui::TextUnformatted(studio.document_ ? "Click an edge of the state graph to open its transition."
                                            : "No design open.");
    ImGui::End();
    return;
  }
  if (!draw_tabs(studio)) {
    ImGui::End();
    return;
  }
  draw_controls(studio);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const Strip strip = place_rows(studio, studio.document_->scene());
  draw_labels(studio, draw, strip);
  draw_scrub(studio, draw, strip);
  draw_bands(studio, draw, strip);
  studio.pip().draw_timeline_marker(draw, studio);
  draw_keys(studio, draw, strip);

  // Playhead over every row.
  const float x = strip.x_of(studio.time_), top = strip.scrub_y;
  draw->AddLine({x, top}, {x, strip.rotation_y + kRowHeight}, IM_COL32(30, 90, 220, 255), 2);
  draw->AddTriangleFilled({x - 6, top}, {x + 6, top}, {x, top + 8}, IM_COL32(30, 90, 220, 255));
  studio.resolve().draw_timeline_hints(draw, studio);
  ImGui::End();
}

bool TimelinePanel::draw_tabs(Studio& studio) {
  const scene::Reconfigurable& scene = studio.document_->scene();
  int close = -1;
  if (ImGui::BeginTabBar("##transitions", ImGuiTabBarFlags_AutoSelectNewTabs)) {
    for (const int transition : studio.open_transitions_) {
      bool keep = true;
      const ImGuiTabItemFlags flags = transition == studio.active_transition_ ? ImGuiTabItemFlags_SetSelected : 0;
      if (ImGui::BeginTabItem(scene.transitions[transition].name.c_str(), &keep, flags)) {
        if (ImGui::IsItemClicked()) studio.open_transition(transition);
        ImGui::EndTabItem();
      } else if (ImGui::IsItemClicked()) {
        studio.open_transition(transition);
      }
      if (!keep) close = transition;
    }
    ImGui::EndTabBar();
  }
  if (close >= 0) studio.close_transition(close);
  return studio.active_transition_ >= 0;
}

void TimelinePanel::draw_controls(Studio& studio) {
  if (ImGui::Button(studio.playing_ ? "Pause" : "Play")) studio.toggle_play();
  ImGui::SameLine();
  float t = static_cast<float>(studio.time_);
  ImGui::SetNextItemWidth(140);
  if (ImGui::SliderFloat("t", &t, 0.0f, 1.0f, "%.3f")) studio.set_time(t);
  ImGui::SameLine();
  ImGui::Checkbox("ghosts", &studio.show_ghosts);
  ImGui::SameLine();
  ImGui::Checkbox("collision boxes", &studio.show_intervals);
  ImGui::SameLine();
  if (ImGui::Button("Best view (V)")) studio.jump_to_best_view();
  ImGui::SameLine();
  ImGui::TextDisabled("Space play   Left/Right step   I key   Del remove key");
}

TimelinePanel::Strip TimelinePanel::place_rows(Studio& studio, const scene::Reconfigurable& scene) {
  const ImVec2 cursor = ImGui::GetCursorScreenPos();
  // Wide enough for "move  <part>" of the longest part name (the same whichever part is
  // selected, so the strip does not shift), up to a quarter of the panel.
  float label_width = kLabelWidth;
  for (const scene::Part& part : scene.parts)
    label_width = std::max(label_width, ImGui::CalcTextSize(("move  " + part.name).c_str()).x + 8);
  label_width = std::min(label_width, std::max(kLabelWidth, ImGui::GetContentRegionAvail().x / 4));
  const float width = std::max(ImGui::GetContentRegionAvail().x - label_width - 8, 50.0f);
  Strip strip;
  strip.label_x = cursor.x;
  strip.label_width = label_width;
  strip.x0 = cursor.x + label_width;
  strip.x1 = strip.x0 + width;
  strip.scrub_y = cursor.y;
  strip.bands_y = strip.scrub_y + kRowHeight + 2;
  strip.translation_y = strip.bands_y + kRowHeight + 2;
  strip.rotation_y = strip.translation_y + kRowHeight + 2;
  Layout& layout = studio.layout_;
  layout.scrub_min = {strip.x0, strip.scrub_y};
  layout.scrub_max = {strip.x1, strip.scrub_y + kRowHeight};
  layout.bands_row_y = strip.bands_y + kRowHeight / 2;
  layout.translation_row_y = strip.translation_y + kRowHeight / 2;
  layout.rotation_row_y = strip.rotation_y + kRowHeight / 2;
  return strip;
}

void TimelinePanel::draw_labels(const Studio& studio, ImDrawList* draw, const Strip& strip) {
  const scene::Reconfigurable& scene = studio.document_->scene();
  const ImU32 label = IM_COL32(70, 70, 80, 255);
  const float x = strip.label_x;
  draw->AddText({x, strip.scrub_y + 3}, label, "time");
  draw->AddText({x, strip.bands_y + 3}, label, "collisions");
  const int part = studio.selected_part_;
  const std::string move_label = part >= 0 ? "move  " + scene.parts[part].name : "move";
  draw->AddText({x, strip.translation_y + 3}, label, fit_text(move_label, strip.label_width - 4).c_str());
  draw->AddText({x, strip.rotation_y + 3}, label, "rotate");
}

void TimelinePanel::draw_scrub(Studio& studio, ImDrawList* draw, const Strip& strip) {
  // Ticks every 0.1.
  const float y = strip.scrub_y;
  draw->AddRectFilled({strip.x0, y}, {strip.x1, y + kRowHeight}, IM_COL32(225, 225, 232, 255));
  for (int i = 0; i <= 10; ++i) {
    const float x = strip.x_of(i / 10.0);
    draw->AddLine({x, y + kRowHeight - 6}, {x, y + kRowHeight}, IM_COL32(110, 110, 120, 255));
    // Right of its tick, but the last one (1.0) left of it, inside the strip, not cut to "1.".
    const std::string tick = fmt::format("{:.1f}", i / 10.0);
    const float text_x = i < 10 ? x + 2 : x - ImGui::CalcTextSize(tick.c_str()).x - 2;
    draw->AddText({text_x, y + 1}, IM_COL32(110, 110, 120, 255), tick.c_str());
  }
  ImGui::SetCursorScreenPos({strip.x0, y});
  ImGui::InvisibleButton("##scrub", {strip.width(), kRowHeight});
  scrubbing_ = ImGui::IsItemActive();
  if (scrubbing_) {
    studio.playing_ = false;
    studio.set_time(strip.t_of(ImGui::GetIO().MousePos.x));
  }
}

void TimelinePanel::draw_bands(Studio& studio, ImDrawList* draw, const Strip& strip) {
  const float y = strip.bands_y, width = strip.width();
  draw->AddRectFilled({strip.x0, y}, {strip.x1, y + kRowHeight}, IM_COL32(240, 240, 244, 255));
  const auto snapshot = studio.collisions();
  const collision::TransitionSnapshot* current = nullptr;
  if (snapshot)
    for (const auto& transition : snapshot->transitions)
      if (transition.transition == studio.active_transition_) current = &transition;
  std::vector<std::pair<double, double>> bands;
  if (current) {
    for (const auto& [a, b] : current->preview)
      draw->AddRectFilled({strip.x_of(a), y + 3}, {std::max(strip.x_of(b), strip.x_of(a) + 2), y + kRowHeight - 3},
                          IM_COL32(240, 150, 60, 70));
    const bool solid = current->up_to_date && snapshot->version == studio.document_->version();
    for (const auto& interval : current->intervals) {
      const ImU32 color = interval.clearance  ? IM_COL32(255, 191, 0, solid ? 230 : 110)  // amber
                          : interval.possible ? IM_COL32(235, 160, 40, solid ? 230 : 110)
                                              : IM_COL32(215, 40, 30, solid ? 230 : 110);
      draw->AddRectFilled({strip.x_of(interval.t0), y + 2},
                          {std::max(strip.x_of(interval.t1), strip.x_of(interval.t0) + 2), y + kRowHeight - 2},
                          color, 3);
      bands.emplace_back(interval.t0, interval.t1);
    }
  }
  ImGui::SetCursorScreenPos({strip.x0, y});
  ImGui::InvisibleButton("##bands", {width, kRowHeight});
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsItemClicked()) {
    const double at = strip.t_of(io.MousePos.x), slack = 4.0 / width;
    for (const auto& [a, b] : bands)
      if (at >= a - slack && at <= b + slack) {
        studio.playing_ = false;
        studio.set_time(a);
        break;
      }
  }
  if (ImGui::IsItemHovered() && current) draw_band_tooltip(studio, *current, strip);
}

void TimelinePanel::draw_band_tooltip(Studio& studio, const collision::TransitionSnapshot& current,
                                      const Strip& strip) {
  const scene::Reconfigurable& scene = studio.document_->scene();
  const double at = strip.t_of(ImGui::GetIO().MousePos.x);
  for (const auto& interval : current.intervals)
    if (std::abs(at - std::clamp(at, interval.t0, interval.t1)) < 4.0 / strip.width()) {
      std::string parts;
      for (const int part : interval.parts) parts += (parts.empty() ? "" : " × ") + scene.parts[part].name;
      ImGui::SetTooltip("%s\nt = %.3f to %.3f%s\nP: show it in the picture-in-picture", parts.c_str(), interval.t0,
                        interval.t1,
                        interval.clearance  ? "\n(clearance: closer than allowed, not colliding)"
                        : interval.possible ? "\n(possible: near miss of the proxies)"
                                            : "");
      if (ImGui::IsKeyPressed(keys::kP, false)) studio.pip().open_on(studio, studio.active_transition_, interval);
    }
}

void TimelinePanel::draw_keys(Studio& studio, ImDrawList* draw, const Strip& strip) {
  for (const float y : {strip.translation_y, strip.rotation_y})
    draw->AddRectFilled({strip.x0, y}, {strip.x1, y + kRowHeight}, IM_COL32(236, 236, 240, 255));
  const scene::KeyframedTrack* track = draw_track_kind(studio, draw, strip);
  std::vector<double> translation_times, rotation_times;
  if (track) {
    for (const auto& key : track->translation) translation_times.push_back(key.time);
    for (const auto& key : track->rotation) rotation_times.push_back(key.time);
  }
  draw_key_row(studio, draw, strip, scene::KeyKind::kTranslation, translation_times);
  draw_key_row(studio, draw, strip, scene::KeyKind::kRotation, rotation_times);
}

const scene::KeyframedTrack* TimelinePanel::draw_track_kind(const Studio& studio, ImDrawList* draw,
                                                            const Strip& strip) {
  if (studio.selected_part_ < 0) return nullptr;
  const scene::Reconfigurable& scene = studio.document_->scene();
  const scene::Transition& transition = scene.transitions[studio.active_transition_];
  const auto it = transition.tracks.find(scene.parts[studio.selected_part_].name);
  if (it == transition.tracks.end()) return nullptr;
  if (const auto* track = std::get_if<scene::KeyframedTrack>(&it->second)) return track;
  // Screw-pose tracks (and parts a linkage drives) show their poses, not draggable keys.
  const bool driven = transition.linkage && transition.linkage->drives(it->first);
  for (const double time : scene::key_times(it->second))
    for (const float y : {strip.translation_y, strip.rotation_y})
      draw->AddCircleFilled({strip.x_of(time), y + kRowHeight / 2}, 2.5f, IM_COL32(120, 90, 160, 255));
  draw->AddText({strip.x0 + 4, strip.rotation_y + 3}, IM_COL32(90, 70, 130, 255),
                driven ? "driven by the transition's linkage" : "screw poses");
  return nullptr;
}

void TimelinePanel::draw_key_row(Studio& studio, ImDrawList* draw, const Strip& strip, scene::KeyKind kind,
                                 const std::vector<double>& times) {
  const ImGuiIO& io = ImGui::GetIO();
  const bool translation = kind == scene::KeyKind::kTranslation;
  const float y = translation ? strip.translation_y : strip.rotation_y;
  ImGui::SetCursorScreenPos({strip.x0 - kDiamond, y});
  ImGui::InvisibleButton(translation ? "##translation-keys" : "##rotation-keys",
                         {strip.width() + 2 * kDiamond, kRowHeight});
  if (ImGui::IsItemClicked()) {
    // Select the diamond under the mouse (and start dragging it), or move the playhead.
    int hit = -1;
    for (int i = 0; i < static_cast<int>(times.size()); ++i)
      if (std::abs(strip.x_of(times[i]) - io.MousePos.x) <= kDiamond + 1) hit = i;
    if (hit >= 0) {
      studio.selected_key_ = KeyRef{kind, hit};
      key_drag_ = studio.selected_key_;
      key_drag_time_ = times[hit];
    } else {
      studio.selected_key_.reset();
      studio.set_time(strip.t_of(io.MousePos.x));
    }
  }
  if (key_drag_ && key_drag_->kind == kind) {
    if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      key_drag_time_ = strip.t_of(io.MousePos.x);
    } else {
      const KeyRef key = *key_drag_;
      key_drag_.reset();
      if (io.MouseDragMaxDistanceSqr[0] > 4 && key.index < static_cast<int>(times.size()) &&
          key_drag_time_ != times[key.index])
        studio.move_key_time(key, key_drag_time_);
    }
  }
  for (int i = 0; i < static_cast<int>(times.size()); ++i) {
    const bool selected = studio.selected_key_ && *studio.selected_key_ == KeyRef{kind, i};
    const bool dragged = key_drag_ && *key_drag_ == KeyRef{kind, i};
    const double at = dragged ? key_drag_time_ : times[i];
    diamond(draw, {strip.x_of(at), y + kRowHeight / 2},
            selected ? IM_COL32(250, 200, 30, 255) : IM_COL32(90, 110, 170, 255), IM_COL32(30, 30, 40, 255));
  }
}

}  // namespace reconfig::studio
