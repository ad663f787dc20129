// The inspector: the selected part's pose at the current time as numbers (editing them sets a
// key or the state pose), the selected key with its Bézier handles, undo/redo, ghost settings
// and the list of collision intervals of the open transition.

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

void Studio::draw_inspector() {
  const PanelRects rects = current_panel_rects();
  begin_panel("Inspector", rects.inspector_pos, rects.inspector_size);
  if (!document_) {
    ImGui::End();
    return;
  }
  const scene::Reconfigurable& scene = document_->scene();

  const char* preview = selected_part_ >= 0 ? scene.parts[selected_part_].name.c_str() : "(click a part)";
  if (ImGui::BeginCombo("part", preview)) {
    for (int p = 0; p < static_cast<int>(scene.parts.size()); ++p)
      if (ImGui::Selectable(scene.parts[p].name.c_str(), p == selected_part_)) select_part(p);
    ImGui::EndCombo();
  }
  if (const auto pose = selected_pose()) {
    ImGui::TextDisabled(active_transition_ < 0 ? "pose in this state"
                        : time_ <= 0 || time_ >= 1 ? "pose at an end: edits the state"
                                                   : "pose at this time: edits set a key");
    Eigen::Vector3d translation = pose->translation;
    if (vector_field("translation", translation)) {
      motion::Pose edited = *pose;
      edited.translation = translation;
      apply_pose(edited);
    }
    if (const auto rotation = rotation_fields("rotation axis", "angle °", pose->rotation)) {
      motion::Pose edited = *pose;
      edited.rotation = *rotation;
      apply_pose(edited);
    }
  }

  // The selected key, with its Bézier handles.
  if (selected_key_ && active_transition_ >= 0 && selected_part_ >= 0) {
    const scene::KeyframedTrack* track = selected_keyframed_track();
    const std::string& transition = scene.transitions[active_transition_].name;
    const std::string& part = scene.parts[selected_part_].name;
    ImGui::Separator();
    if (track && selected_key_->kind == scene::KeyKind::kTranslation &&
        selected_key_->index < static_cast<int>(track->translation.size())) {
      motion::TranslationKey key = track->translation[selected_key_->index];
      ImGui::Text("translation key %d at t = %.3f", selected_key_->index, key.time);
      bool changed = vector_field("point", key.point);
      changed = vector_field("in handle", key.in) || changed;
      changed = vector_field("out handle", key.out) || changed;
      if (changed) execute(scene::set_translation_key(transition, part, selected_key_->index, key));
    } else if (track && selected_key_->kind == scene::KeyKind::kRotation &&
               selected_key_->index < static_cast<int>(track->rotation.size())) {
      motion::RotationKey key = track->rotation[selected_key_->index];
      ImGui::Text("rotation key %d at t = %.3f", selected_key_->index, key.time);
      if (const auto rotation = rotation_fields("key axis", "key angle °", key.rotation)) {
        key.rotation = *rotation;
        execute(scene::set_rotation_key(transition, part, selected_key_->index, key));
      }
    }
    if (ImGui::Button("Remove key (Del)")) delete_selected_key();
  }
  if (ImGui::Button("Insert key (I)")) insert_key();
  draw_resolve_section();
  sculpt_.draw(*this);

  ImGui::Separator();
  ImGui::BeginDisabled(document_->undo_label().empty());
  if (ImGui::Button("Undo")) undo();
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(document_->redo_label().empty());
  if (ImGui::Button("Redo")) redo();
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::TextDisabled("%s", document_->undo_label().c_str());

  ImGui::Separator();
  ImGui::Checkbox("ghosts", &show_ghosts);
  ImGui::SliderInt("ghost count", &ghost_count, 1, 8);
  ImGui::SliderFloat("ghost spacing", &ghost_spacing, 0.01f, 0.25f, "%.2f");

  // The collision intervals of the open transition; clicking one jumps to it.
  if (const auto snapshot = collisions(); snapshot && active_transition_ >= 0) {
    ImGui::Separator();
    for (const auto& transition : snapshot->transitions) {
      if (transition.transition != active_transition_) continue;
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
        const bool chosen = ImGui::Selectable(label.c_str(), interval.t0 <= time_ && time_ <= interval.t1);
        if (interval.clearance) ImGui::PopStyleColor();
        if (chosen) {
          playing_ = false;
          set_time(interval.t0);
        }
      }
    }
  }
  ImGui::End();
}

}  // namespace reconfig::studio
