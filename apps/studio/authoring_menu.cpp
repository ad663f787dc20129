#include "authoring_menu.h"

#include <fmt/format.h>

#include <cstdio>

#include "reconfig/scene/part_edits.h"
#include "reconfig/scene/state_edits.h"
#include "studio.h"

namespace reconfig::studio {

namespace fs = std::filesystem;

namespace {

using Kind = AuthoringDialog::Kind;

/// A text field over `text` (1 KiB at most); true when Enter was pressed in it.
bool text_field(const char* label, std::string& text) {
  char buffer[1024];
  std::snprintf(buffer, sizeof buffer, "%s", text.c_str());
  ImGui::SetNextItemWidth(420);
  const bool entered = ImGui::InputText(label, buffer, sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue);
  text = buffer;
  return entered;
}

/// The paths of a list separated by ';' (blanks around each trimmed).
std::vector<fs::path> split_paths(const std::string& text) {
  std::vector<fs::path> paths;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(';', start), text.size());
    std::string item = text.substr(start, end - start);
    const auto first = item.find_first_not_of(" \t"), last = item.find_last_not_of(" \t");
    if (first != std::string::npos) paths.emplace_back(item.substr(first, last - first + 1));
    start = end + 1;
  }
  return paths;
}

const char* dialog_title(Kind kind) {
  switch (kind) {
    case Kind::kNewDesign: return "New design";
    case Kind::kImportMeshes: return "Import mesh";
    case Kind::kAddPrimitive: return "Add primitive";
    case Kind::kRenamePart: return "Rename part";
    case Kind::kRecolorPart: return "Part color";
    case Kind::kReplaceMesh: return "Replace mesh";
    case Kind::kDeletePart: return "Delete part?";
    case Kind::kAddState: return "Add state";
    case Kind::kRenameState: return "Rename state";
    case Kind::kDeleteState: return "Delete state?";
    case Kind::kAddTransition: return "Add transition";
    case Kind::kRenameTransition: return "Rename transition";
    case Kind::kDuplicate: return "Duplicate";
  }
  return "";
}

}  // namespace

void AuthoringMenus::draw_file_items(Studio& studio) {
  if (ImGui::MenuItem("New...")) dialog_ = AuthoringDialog{.kind = Kind::kNewDesign, .text = "untitled.json"};
  if (ImGui::MenuItem("Import mesh...", nullptr, false, studio.document() != nullptr))
    dialog_ = AuthoringDialog{.kind = Kind::kImportMeshes};
}

void AuthoringMenus::draw_design_menu(Studio& studio) {
  if (!studio.document() || !ImGui::BeginMenu("Design")) return;
  const scene::Reconfigurable& scene = studio.document()->scene();
  if (ImGui::MenuItem("Add primitive...")) dialog_ = AuthoringDialog{.kind = Kind::kAddPrimitive, .text = "box"};
  draw_part_menu(studio);
  ImGui::Separator();
  if (ImGui::MenuItem("Add state from the view..."))
    dialog_ = AuthoringDialog{.kind = Kind::kAddState, .text = fmt::format("state_{}", scene.states.size() + 1)};
  draw_state_menu(studio);
  ImGui::Separator();
  const int shown = studio.active_state_;
  if (ImGui::MenuItem("Add transition..."))
    dialog_ = AuthoringDialog{.kind = Kind::kAddTransition, .from = shown,
                              .to = std::min<int>(shown + 1, static_cast<int>(scene.states.size()) - 1)};
  draw_transition_menu(studio);
  ImGui::EndMenu();
}

void AuthoringMenus::draw_part_menu(Studio& studio) {
  const scene::Reconfigurable& scene = studio.document()->scene();
  const int selected = studio.selected_part();
  const bool part = selected >= 0;
  const std::string part_name = part ? scene.parts[selected].name : "";
  if (!ImGui::BeginMenu(part ? fmt::format("Part {}", part_name).c_str() : "Part (select one)", part)) return;
  if (ImGui::MenuItem("Rename..."))
    dialog_ = AuthoringDialog{.kind = Kind::kRenamePart, .target = selected, .text = part_name};
  if (ImGui::MenuItem("Color...")) {
    AuthoringDialog dialog{.kind = Kind::kRecolorPart, .target = selected};
    if (const auto& c = scene.parts[selected].color)
      dialog.color = {static_cast<float>(c->x()), static_cast<float>(c->y()), static_cast<float>(c->z())};
    dialog_ = dialog;
  }
  if (ImGui::MenuItem("Duplicate..."))
    dialog_ = AuthoringDialog{.kind = Kind::kDuplicate, .target = selected, .text = part_name + "_copy"};
  if (ImGui::MenuItem("Replace mesh...")) dialog_ = AuthoringDialog{.kind = Kind::kReplaceMesh, .target = selected};
  if (ImGui::MenuItem("Delete")) {
    // A part no transition moves goes at once (undo brings it back); else ask first.
    std::vector<std::string> moving;
    for (const scene::Transition& transition : scene.transitions)
      if (transition.tracks.count(part_name)) moving.push_back(transition.name);
    if (moving.empty()) studio.execute(scene::delete_part(part_name));
    else
      dialog_ = AuthoringDialog{
          .kind = Kind::kDeletePart, .target = selected,
          .message = fmt::format("{} moves in {}: delete it with its keys there?", part_name, fmt::join(moving, ", "))};
  }
  ImGui::EndMenu();
}

void AuthoringMenus::draw_state_menu(Studio& studio) {
  const scene::Reconfigurable& scene = studio.document()->scene();
  const int state = studio.active_transition() < 0 ? studio.active_state_ : -1;
  if (!ImGui::BeginMenu(state >= 0 ? fmt::format("State {}", scene.states[state].name).c_str() : "State (show one)",
                        state >= 0))
    return;
  const std::string& name = scene.states[state].name;
  if (ImGui::MenuItem("Rename...")) dialog_ = AuthoringDialog{.kind = Kind::kRenameState, .target = state, .text = name};
  if (ImGui::MenuItem("Delete", nullptr, false, scene.states.size() > 1)) {
    std::vector<std::string> using_it;
    for (const scene::Transition& transition : scene.transitions)
      if (transition.from == name || transition.to == name) using_it.push_back(transition.name);
    if (using_it.empty()) studio.execute(scene::delete_state(name));
    else
      dialog_ = AuthoringDialog{.kind = Kind::kDeleteState, .target = state,
                                .message = fmt::format("{} is an end of {}: delete them too?", name,
                                                       fmt::join(using_it, ", "))};
  }
  ImGui::EndMenu();
}

void AuthoringMenus::draw_transition_menu(Studio& studio) {
  const scene::Reconfigurable& scene = studio.document()->scene();
  const int transition = studio.active_transition();
  if (!ImGui::BeginMenu(transition >= 0 ? fmt::format("Transition {}", scene.transitions[transition].name).c_str()
                                        : "Transition (open one)",
                        transition >= 0))
    return;
  const std::string& name = scene.transitions[transition].name;
  if (ImGui::MenuItem("Rename..."))
    dialog_ = AuthoringDialog{.kind = Kind::kRenameTransition, .target = transition, .text = name};
  if (ImGui::MenuItem("Reverse")) studio.execute(scene::reverse_transition(name));
  if (ImGui::MenuItem("Duplicate as an alternative..."))
    dialog_ = AuthoringDialog{.kind = Kind::kDuplicate, .target = transition, .transition = true, .text = name + "_2"};
  if (ImGui::MenuItem("Delete")) studio.execute(scene::delete_transition(name));
  ImGui::EndMenu();
}

void AuthoringMenus::draw_dialog(Studio& studio) {
  if (!dialog_) return;
  AuthoringDialog& dialog = *dialog_;
  const char* title = dialog_title(dialog.kind);
  if (!dialog.opened) {
    ImGui::OpenPopup(title);
    dialog.opened = true;
  }
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    dialog_.reset();  // closed by ImGui (Escape)
    return;
  }
  const bool entered = draw_fields(studio, dialog);
  const bool destructive = dialog.kind == Kind::kDeletePart || dialog.kind == Kind::kDeleteState;
  bool close = false;
  if (entered || ImGui::Button(destructive ? "Delete" : "OK")) {
    accept(studio, dialog);
    close = true;
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) close = true;
  if (close) {
    ImGui::CloseCurrentPopup();
    dialog_.reset();
  }
  ImGui::EndPopup();
}

bool AuthoringMenus::draw_fields(const Studio& studio, AuthoringDialog& dialog) {
  const scene::Reconfigurable* scene = studio.document() ? &studio.document()->scene() : nullptr;
  switch (dialog.kind) {
    case Kind::kNewDesign:
      ImGui::TextUnformatted("The file the new design will be saved as:");
      return text_field("##path", dialog.text);
    case Kind::kImportMeshes:
    case Kind::kReplaceMesh:
      ImGui::TextUnformatted(dialog.kind == Kind::kImportMeshes
                                 ? "Mesh files (OBJ, STL, PLY, OFF, glTF/GLB), separated by ';':"
                                 : "The mesh file (the part keeps its pivot and poses):");
      return text_field("##path", dialog.text);
    case Kind::kAddPrimitive: {
      ImGui::Combo("shape", &dialog.shape, "box\0cylinder\0sphere\0");
      const bool entered = text_field("name", dialog.text);
      if (dialog.shape == 0) ImGui::InputScalarN("size x, y, z", ImGuiDataType_Double, dialog.sizes.data(), 3);
      if (dialog.shape == 1) ImGui::InputScalarN("radius, height", ImGuiDataType_Double, dialog.sizes.data(), 2);
      if (dialog.shape == 2) ImGui::InputDouble("radius", dialog.sizes.data());
      return entered;
    }
    case Kind::kRecolorPart: ImGui::ColorEdit3("color", dialog.color.data()); return false;
    case Kind::kDeletePart:
    case Kind::kDeleteState: ImGui::TextUnformatted(dialog.message.c_str()); return false;
    case Kind::kAddTransition: {
      const auto state_combo = [&](const char* label, int& index) {
        if (!ImGui::BeginCombo(label, index < static_cast<int>(scene->states.size()) ? scene->states[index].name.c_str() : ""))
          return;
        for (int s = 0; s < static_cast<int>(scene->states.size()); ++s)
          if (ImGui::Selectable(scene->states[s].name.c_str(), s == index)) index = s;
        ImGui::EndCombo();
      };
      if (scene) {
        state_combo("from", dialog.from);
        state_combo("to", dialog.to);
      }
      ImGui::Combo("motion", &dialog.choreography, "straight (Bezier + slerp)\0screw\0");
      return text_field("name (empty: FROM_to_TO)", dialog.text);
    }
    default: return text_field("name", dialog.text);
  }
}

bool AuthoringMenus::accept(Studio& studio, const AuthoringDialog& dialog) {
  if (dialog.kind == Kind::kNewDesign) return studio.new_design(dialog.text);
  if (!studio.document()) return false;
  switch (dialog.kind) {
    case Kind::kImportMeshes: return studio.import_meshes(split_paths(dialog.text));
    case Kind::kAddPrimitive: {
      const auto& s = dialog.sizes;
      const scene::PartSource source = dialog.shape == 0   ? scene::PartSource{scene::BoxPrimitive{{s[0], s[1], s[2]}}}
                                       : dialog.shape == 1 ? scene::PartSource{scene::CylinderPrimitive{s[0], s[1]}}
                                                           : scene::PartSource{scene::SpherePrimitive{s[0]}};
      if (!studio.execute(scene::add_primitive_part(dialog.text, source))) return false;
      studio.select_part(studio.document()->scene().find_part(dialog.text));
      return true;
    }
    case Kind::kAddState: return studio.add_state_from_view(dialog.text);
    case Kind::kAddTransition:
      return studio.add_transition_between(
          dialog.from, dialog.to, dialog.choreography == 1 ? scene::Choreography::kScrew : scene::Choreography::kStraight,
          dialog.text);
    default: return accept_edit(studio, dialog);
  }
}

bool AuthoringMenus::accept_edit(Studio& studio, const AuthoringDialog& dialog) {
  const scene::Reconfigurable& scene = studio.document()->scene();
  const auto valid = [](int index, std::size_t count) { return index >= 0 && index < static_cast<int>(count); };
  const bool part = valid(dialog.target, scene.parts.size()), state = valid(dialog.target, scene.states.size());
  const bool transition = valid(dialog.target, scene.transitions.size());
  switch (dialog.kind) {
    case Kind::kRenamePart: return part && studio.execute(scene::rename_part(scene.parts[dialog.target].name, dialog.text));
    case Kind::kRecolorPart:
      return part && studio.execute(scene::recolor_part(scene.parts[dialog.target].name,
                                                        Eigen::Vector3f(dialog.color.data()).cast<double>()));
    case Kind::kReplaceMesh: return studio.replace_part_mesh_from(dialog.target, dialog.text);
    case Kind::kDeletePart: return part && studio.execute(scene::delete_part(scene.parts[dialog.target].name, true));
    case Kind::kRenameState:
      return state && studio.execute(scene::rename_state(scene.states[dialog.target].name, dialog.text));
    case Kind::kDeleteState: return state && studio.execute(scene::delete_state(scene.states[dialog.target].name, true));
    case Kind::kRenameTransition:
      return transition && studio.execute(scene::rename_transition(scene.transitions[dialog.target].name, dialog.text));
    case Kind::kDuplicate:
      if (dialog.transition)
        return transition && studio.execute(scene::duplicate_transition(scene.transitions[dialog.target].name, dialog.text));
      return part && studio.execute(scene::duplicate_part(scene.parts[dialog.target].name, dialog.text));
    default: return false;
  }
}

}  // namespace reconfig::studio
