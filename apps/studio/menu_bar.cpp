// The main menu: File (open, save, save as, quit), Edit (undo, redo), View, Collisions, Transitions.

#include "authoring_menu.h"
#include "studio.h"

namespace reconfig::studio {

void Studio::draw_menu_bar() {
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("Open...", "Ctrl+O")) show_open_dialog_ = true;
    if (ImGui::MenuItem("Open linkage...")) linkage_panel_.request_open_dialog();
    authoring().draw_file_items(*this);
    if (ImGui::MenuItem("Save", "Ctrl+S", false, document_ != nullptr)) save();
    if (ImGui::MenuItem("Save as...", nullptr, false, document_ != nullptr)) {
      save_path_input_ = document_->file().string();
      show_save_as_dialog_ = true;
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Quit")) request_close();
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Edit", document_ != nullptr)) {
    const std::string undo_label = "Undo " + document_->undo_label(), redo_label = "Redo " + document_->redo_label();
    if (ImGui::MenuItem(undo_label.c_str(), "Ctrl+Z", false, !document_->undo_label().empty())) undo();
    if (ImGui::MenuItem(redo_label.c_str(), "Ctrl+Shift+Z", false, !document_->redo_label().empty())) redo();
    ImGui::Separator();
    if (ImGui::MenuItem("Insert key", "I")) insert_key();
    if (ImGui::MenuItem("Remove key", "Del", false, selected_key_.has_value())) delete_selected_key();
    ImGui::EndMenu();
  }
  authoring().draw_design_menu(*this);
  if (ImGui::BeginMenu("View")) {
    if (ImGui::MenuItem("Frame all", "F")) frame_all();
    ImGui::MenuItem("Ghosts", nullptr, &show_ghosts);
    ImGui::MenuItem("Collision boxes", nullptr, &show_intervals);
    const bool driven = document_ && active_transition_ >= 0 && document_->scene().transitions[active_transition_].linkage;
    if (ImGui::MenuItem("Linkage editor", nullptr, linkage_panel_.shown(), driven || linkage_panel_.lone())) {
      if (linkage_panel_.shown()) linkage_panel_.close();
      else linkage_panel_.open_drive(*this, active_transition_);
    }
    if (bool envelope = shaping_.envelope_shown(); ImGui::MenuItem("Swept envelope of the selected part", nullptr, &envelope))
      shaping_.set_envelope_shown(envelope);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Collisions")) {
    if (ImGui::MenuItem("Settings...")) show_collision_settings();
    if (ImGui::MenuItem("Hint for the selected part", "H", false, document_ && selected_part_ >= 0)) request_hint();
    if (ImGui::MenuItem("Resolve this transition automatically", nullptr, false,
                        document_ && active_transition_ >= 0 && !auto_resolving()))
      start_auto_resolve();
    if (ImGui::MenuItem("Carve...", nullptr, false, document_ && selected_part_ >= 0 && active_transition_ >= 0 &&
                                                        !shaping_.carving()))
      shaping_.show_carve_window(*this);
    ImGui::EndMenu();
  }
  if (document_ && ImGui::BeginMenu("Transitions")) {
    const auto& transitions = document_->scene().transitions;
    for (int k = 0; k < static_cast<int>(transitions.size()); ++k)
      if (ImGui::MenuItem(transitions[k].name.c_str(), nullptr, k == active_transition_)) open_transition(k);
    ImGui::EndMenu();
  }
  if (document_) {
    const std::string title = document_->file().filename().string() + (document_->modified() ? " *" : "");
    ImGui::SameLine(ImGui::GetWindowWidth() - ImGui::CalcTextSize(title.c_str()).x - 16);
    ImGui::TextUnformatted(title.c_str());
  }
  ImGui::EndMainMenuBar();
}

}  // namespace reconfig::studio
