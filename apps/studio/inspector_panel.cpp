#include "inspector_panel.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "axis_angle.h"
#include "counted.h"
#include "interval_kinds.h"
#include "interval_label.h"
#include "panel_window.h"
#include "resolve_panel.h"
#include "studio.h"

namespace reconfig::studio {
namespace {

/// A double[3] field; true once an edit is finished (Enter or leaving the field).
bool vector_field(const char* label, Eigen::Vector3d& value) {
  ImGui::InputScalarN(label, ImGuiDataType_Double, value.data(), 3, nullptr, nullptr, "%.4f");
  return ImGui::IsItemDeactivatedAfterEdit();
}

/// The rotation `q` as an axis field and an angle field; the edited rotation once an edit of
/// either is finished (and the axis is not zero).
std::optional<Eigen::Quaterniond> rotation_fields(const char* axis_label, const char* angle_label,
                                                  const Eigen::Quaterniond& q) {
  AxisAngle shown = axis_angle_of(q);
  bool edited = vector_field(axis_label, shown.axis);
  ImGui::InputDouble(angle_label, &shown.degrees, 0, 0, "%.3f");
  edited = ImGui::IsItemDeactivatedAfterEdit() || edited;
  return edited ? rotation_of(shown) : std::nullopt;
}

}  // namespace

void InspectorPanel::draw(Studio& studio) {
  const PanelRects rects = current_panel_rects();
  begin_panel("Inspector", rects.inspector_pos, rects.inspector_size);
  if (!studio.document()) {
    ImGui::End();
    return;
  }
  draw_part(studio);
  draw_selected_key(studio);
  if (ImGui::Button("Insert key (I)")) studio.insert_key();
  studio.resolve().draw(studio);
  studio.sculpt().draw(studio);
  draw_history(studio);
  draw_ghosts(studio);
  draw_intervals(studio);
  ImGui::End();
}

void InspectorPanel::draw_part(Studio& studio) {
  const scene::Reconfigurable& scene = studio.document()->scene();
  const int selected = studio.selected_part();
  const char* preview = selected >= 0 ? scene.parts[selected].name.c_str() : "(click a part)";
  if (ImGui::BeginCombo("part", preview)) {
    for (int p = 0; p < static_cast<int>(scene.parts.size()); ++p)
      if (ImGui::Selectable(scene.parts[p].name.c_str(), p == selected)) studio.select_part(p);
    ImGui::EndCombo();
  }
  const auto pose = studio.selected_pose();
  if (!pose) return;
  const double time = studio.time();
  ImGui::TextDisabled(studio.active_transition() < 0 ? "pose in this state"
                      : time <= 0 || time >= 1       ? "pose at an end: edits the state"
                                                     : "pose at this time: edits set a key");
  Eigen::Vector3d translation = pose->translation;
  if (vector_field("translation", translation)) {
    motion::Pose edited = *pose;
    edited.translation = translation;
    studio.apply_pose(edited);
  }
  if (const auto rotation = rotation_fields("rotation axis", "angle °", pose->rotation)) {
    motion::Pose edited = *pose;
    edited.rotation = *rotation;
    studio.apply_pose(edited);
  }
}

void InspectorPanel::draw_selected_key(Studio& studio) {
  // The selected key, with its Bézier handles.
  const std::optional<KeyRef> selected = studio.selected_key();
  if (!selected || studio.active_transition() < 0 || studio.selected_part() < 0) return;
  const scene::Reconfigurable& scene = studio.document()->scene();
  const scene::KeyframedTrack* track = studio.selected_keyframed_track();
  const std::string& transition = scene.transitions[studio.active_transition()].name;
  const std::string& part = scene.parts[studio.selected_part()].name;
  ImGui::Separator();
  if (track && selected->kind == scene::KeyKind::kTranslation &&
      selected->index < static_cast<int>(track->translation.size())) {
    motion::TranslationKey key = track->translation[selected->index];
    ImGui::Text("translation key %d at t = %.3f", selected->index, key.time);
    bool changed = vector_field("point", key.point);
    changed = vector_field("in handle", key.in) || changed;
    changed = vector_field("out handle", key.out) || changed;
    if (changed) studio.execute(scene::set_translation_key(transition, part, selected->index, key));
  } else if (track && selected->kind == scene::KeyKind::kRotation &&
             selected->index < static_cast<int>(track->rotation.size())) {
    motion::RotationKey key = track->rotation[selected->index];
    ImGui::Text("rotation key %d at t = %.3f", selected->index, key.time);
    if (const auto rotation = rotation_fields("key axis", "key angle °", key.rotation)) {
      key.rotation = *rotation;
      studio.execute(scene::set_rotation_key(transition, part, selected->index, key));
    }
  }
  if (ImGui::Button("Remove key (Del)")) studio.delete_selected_key();
}

void InspectorPanel::draw_history(Studio& studio) {
  const Document& document = *studio.document();
  ImGui::Separator();
  ImGui::BeginDisabled(document.undo_label().empty());
  if (ImGui::Button("Undo")) studio.undo();
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(document.redo_label().empty());
  if (ImGui::Button("Redo")) studio.redo();
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::TextDisabled("%s", document.undo_label().c_str());
}

void InspectorPanel::draw_ghosts(Studio& studio) {
  ImGui::Separator();
  ImGui::Checkbox("ghosts", &studio.show_ghosts);
  ImGui::SliderInt("ghost count", &studio.ghost_count, 1, 8);
  ImGui::SliderFloat("ghost spacing", &studio.ghost_spacing, 0.01f, 0.25f, "%.2f");
}

void InspectorPanel::draw_intervals(Studio& studio) {
  const auto snapshot = studio.collisions();
  const int active = studio.active_transition();
  if (!snapshot || active < 0) return;
  const scene::Reconfigurable& scene = studio.document()->scene();
  const double time = studio.time();
  ImGui::Separator();
  for (const auto& transition : snapshot->transitions) {
    if (transition.transition != active) continue;
    const std::size_t clearances = clearance_count(transition.intervals);
    ImGui::Text("%s%s%s", counted(transition.intervals.size() - clearances, "collision interval").c_str(),
                clearances > 0 ? fmt::format(", {}", counted(clearances, "clearance interval")).c_str() : "",
                transition.up_to_date ? "" : " (detecting...)");
    for (std::size_t i = 0; i < transition.intervals.size(); ++i) {
      const auto& interval = transition.intervals[i];
      std::vector<std::string> parts;
      for (const int p : interval.parts) parts.push_back(scene.parts[p].name);
      const std::string label = fmt::format(
          "{}##ci{}", interval_label(interval.t0, interval.t1, parts, ImGui::GetContentRegionAvail().x), i);
      if (interval.clearance) ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(200, 140, 0, 255));  // amber
      const bool chosen = ImGui::Selectable(label.c_str(), interval.t0 <= time && time <= interval.t1);
      if (interval.clearance) ImGui::PopStyleColor();
      if (chosen) {
        studio.playing_ = false;
        studio.set_time(interval.t0);
      }
    }
  }
}

}  // namespace reconfig::studio
