// The authoring menus: File > New / Import mesh, the Design menu (parts, states, transitions),
// their dialogs, and the state graph's right-click menus and node-to-node drags. Each item
// ends in one of the studio's authoring actions (authoring.cpp) or a scene command; bad input
// is a message in the status bar, never a crash, and the design stays as it was.

#include <fmt/format.h>

#include <cmath>
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

void Studio::draw_file_authoring_items() {
  if (ImGui::MenuItem("New...")) authoring_dialog_ = AuthoringDialog{.kind = Kind::kNewDesign, .text = "untitled.json"};
  if (ImGui::MenuItem("Import mesh...", nullptr, false, document_ != nullptr))
    authoring_dialog_ = AuthoringDialog{.kind = Kind::kImportMeshes};
}

void Studio::draw_design_menu() {
  if (!document_ || !ImGui::BeginMenu("Design")) return;
  const scene::Reconfigurable& scene = document_->scene();
  if (ImGui::MenuItem("Add primitive...")) authoring_dialog_ = AuthoringDialog{.kind = Kind::kAddPrimitive, .text = "box"};
  const bool part = selected_part_ >= 0;
  const std::string part_name = part ? scene.parts[selected_part_].name : "";
  if (ImGui::BeginMenu(part ? fmt::format("Part {}", part_name).c_str() : "Part (select one)", part)) {
    if (ImGui::MenuItem("Rename..."))
      authoring_dialog_ = AuthoringDialog{.kind = Kind::kRenamePart, .target = selected_part_, .text = part_name};
    if (ImGui::MenuItem("Color...")) {
      AuthoringDialog dialog{.kind = Kind::kRecolorPart, .target = selected_part_};
      if (const auto& c = scene.parts[selected_part_].color)
        dialog.color = {static_cast<float>(c->x()), static_cast<float>(c->y()), static_cast<float>(c->z())};
      authoring_dialog_ = dialog;
    }
    if (ImGui::MenuItem("Duplicate..."))
      authoring_dialog_ = AuthoringDialog{.kind = Kind::kDuplicate, .target = selected_part_, .text = part_name + "_copy"};
    if (ImGui::MenuItem("Replace mesh...")) authoring_dialog_ = AuthoringDialog{.kind = Kind::kReplaceMesh, .target = selected_part_};
    if (ImGui::MenuItem("Delete")) {
      // A part no transition moves goes at once (undo brings it back); else ask first.
      std::vector<std::string> moving;
      for (const scene::Transition& transition : scene.transitions)
        if (transition.tracks.count(part_name)) moving.push_back(transition.name);
      if (moving.empty()) execute(scene::delete_part(part_name));
      else
        authoring_dialog_ = AuthoringDialog{
            .kind = Kind::kDeletePart, .target = selected_part_,
            .message = fmt::format("{} moves in {}: delete it with its keys there?", part_name, fmt::join(moving, ", "))};
    }
    ImGui::EndMenu();
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Add state from the view..."))
    authoring_dialog_ = AuthoringDialog{.kind = Kind::kAddState, .text = fmt::format("state_{}", scene.states.size() + 1)};
  const int state = active_transition_ < 0 ? active_state_ : -1;
  if (ImGui::BeginMenu(state >= 0 ? fmt::format("State {}", scene.states[state].name).c_str() : "State (show one)",
                       state >= 0)) {
    if (ImGui::MenuItem("Rename..."))
      authoring_dialog_ = AuthoringDialog{.kind = Kind::kRenameState, .target = state, .text = scene.states[state].name};
    if (ImGui::MenuItem("Delete", nullptr, false, scene.states.size() > 1)) {
      std::vector<std::string> using_it;
      for (const scene::Transition& transition : scene.transitions)
        if (transition.from == scene.states[state].name || transition.to == scene.states[state].name)
          using_it.push_back(transition.name);
      if (using_it.empty()) execute(scene::delete_state(scene.states[state].name));
      else
        authoring_dialog_ = AuthoringDialog{.kind = Kind::kDeleteState, .target = state,
                                            .message = fmt::format("{} is an end of {}: delete them too?",
                                                                   scene.states[state].name, fmt::join(using_it, ", "))};
    }
    ImGui::EndMenu();
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Add transition..."))
    authoring_dialog_ = AuthoringDialog{.kind = Kind::kAddTransition, .from = active_state_,
                                        .to = std::min<int>(active_state_ + 1, static_cast<int>(scene.states.size()) - 1)};
  const int transition = active_transition_;
  if (ImGui::BeginMenu(transition >= 0 ? fmt::format("Transition {}", scene.transitions[transition].name).c_str()
                                       : "Transition (open one)",
                       transition >= 0)) {
    const std::string& name = scene.transitions[transition].name;
    if (ImGui::MenuItem("Rename..."))
      authoring_dialog_ = AuthoringDialog{.kind = Kind::kRenameTransition, .target = transition, .text = name};
    if (ImGui::MenuItem("Reverse")) execute(scene::reverse_transition(name));
    if (ImGui::MenuItem("Duplicate as an alternative..."))
      authoring_dialog_ =
          AuthoringDialog{.kind = Kind::kDuplicate, .target = transition, .transition = true, .text = name + "_2"};
    if (ImGui::MenuItem("Delete")) execute(scene::delete_transition(name));
    ImGui::EndMenu();
  }
  ImGui::EndMenu();
}

void Studio::draw_authoring_dialogs() {
  if (!authoring_dialog_) return;
  AuthoringDialog& dialog = *authoring_dialog_;
  const char* title = dialog_title(dialog.kind);
  if (!dialog.opened) {
    ImGui::OpenPopup(title);
    dialog.opened = true;
  }
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    authoring_dialog_.reset();  // closed by ImGui (Escape)
    return;
  }
  bool entered = false;
  const scene::Reconfigurable* scene = document_ ? &document_->scene() : nullptr;
  switch (dialog.kind) {
    case Kind::kNewDesign:
      ImGui::TextUnformatted("The file the new design will be saved as:");
      entered = text_field("##path", dialog.text);
      break;
    case Kind::kImportMeshes:
    case Kind::kReplaceMesh:
      ImGui::TextUnformatted(dialog.kind == Kind::kImportMeshes
                                 ? "Mesh files (OBJ, STL, PLY, OFF, glTF/GLB), separated by ';':"
                                 : "The mesh file (the part keeps its pivot and poses):");
      entered = text_field("##path", dialog.text);
      break;
    case Kind::kAddPrimitive: {
      ImGui::Combo("shape", &dialog.shape, "box\0cylinder\0sphere\0");
      entered = text_field("name", dialog.text);
      if (dialog.shape == 0) ImGui::InputScalarN("size x, y, z", ImGuiDataType_Double, dialog.sizes.data(), 3);
      if (dialog.shape == 1) ImGui::InputScalarN("radius, height", ImGuiDataType_Double, dialog.sizes.data(), 2);
      if (dialog.shape == 2) ImGui::InputDouble("radius", dialog.sizes.data());
      break;
    }
    case Kind::kRecolorPart: ImGui::ColorEdit3("color", dialog.color.data()); break;
    case Kind::kDeletePart:
    case Kind::kDeleteState: ImGui::TextUnformatted(dialog.message.c_str()); break;
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
      entered = text_field("name (empty: FROM_to_TO)", dialog.text);
      break;
    }
    default: entered = text_field("name", dialog.text); break;
  }
  const bool destructive = dialog.kind == Kind::kDeletePart || dialog.kind == Kind::kDeleteState;
  bool close = false;
  if (entered || ImGui::Button(destructive ? "Delete" : "OK")) {
    accept_authoring_dialog(dialog);
    close = true;
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) close = true;
  if (close) {
    ImGui::CloseCurrentPopup();
    authoring_dialog_.reset();
  }
  ImGui::EndPopup();
}

bool Studio::accept_authoring_dialog(const AuthoringDialog& dialog) {
  if (dialog.kind == Kind::kNewDesign) return new_design(dialog.text);
  if (!document_) return false;
  const scene::Reconfigurable& scene = document_->scene();
  const auto valid = [](int index, std::size_t count) { return index >= 0 && index < static_cast<int>(count); };
  switch (dialog.kind) {
    case Kind::kImportMeshes: return import_meshes(split_paths(dialog.text));
    case Kind::kAddPrimitive: {
      const auto& s = dialog.sizes;
      const scene::PartSource source = dialog.shape == 0   ? scene::PartSource{scene::BoxPrimitive{{s[0], s[1], s[2]}}}
                                       : dialog.shape == 1 ? scene::PartSource{scene::CylinderPrimitive{s[0], s[1]}}
                                                           : scene::PartSource{scene::SpherePrimitive{s[0]}};
      if (!execute(scene::add_primitive_part(dialog.text, source))) return false;
      select_part(document_->scene().find_part(dialog.text));
      return true;
    }
    case Kind::kAddState: return add_state_from_view(dialog.text);
    case Kind::kAddTransition:
      return add_transition_between(dialog.from, dialog.to,
                                    dialog.choreography == 1 ? scene::Choreography::kScrew : scene::Choreography::kStraight,
                                    dialog.text);
    default: break;
  }
  const bool part = valid(dialog.target, scene.parts.size()), state = valid(dialog.target, scene.states.size());
  const bool transition = valid(dialog.target, scene.transitions.size());
  switch (dialog.kind) {
    case Kind::kRenamePart: return part && execute(scene::rename_part(scene.parts[dialog.target].name, dialog.text));
    case Kind::kRecolorPart:
      return part && execute(scene::recolor_part(scene.parts[dialog.target].name,
                                                 Eigen::Vector3f(dialog.color.data()).cast<double>()));
    case Kind::kReplaceMesh: return replace_part_mesh_from(dialog.target, dialog.text);
    case Kind::kDeletePart: return part && execute(scene::delete_part(scene.parts[dialog.target].name, true));
    case Kind::kRenameState: return state && execute(scene::rename_state(scene.states[dialog.target].name, dialog.text));
    case Kind::kDeleteState: return state && execute(scene::delete_state(scene.states[dialog.target].name, true));
    case Kind::kRenameTransition:
      return transition && execute(scene::rename_transition(scene.transitions[dialog.target].name, dialog.text));
    case Kind::kDuplicate:
      if (dialog.transition)
        return transition && execute(scene::duplicate_transition(scene.transitions[dialog.target].name, dialog.text));
      return part && execute(scene::duplicate_part(scene.parts[dialog.target].name, dialog.text));
    default: return false;
  }
}

void Studio::handle_graph_authoring(const std::vector<ImVec2>& nodes, const std::vector<ImVec2>& badges,
                                    float node_radius) {
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const auto hit = [&](const std::vector<ImVec2>& points, float radius) {
    for (int k = 0; k < static_cast<int>(points.size()); ++k)
      if (std::hypot(mouse.x - points[k].x, mouse.y - points[k].y) <= radius) return k;
    return -1;
  };
  // Drag from a node to another (or the same one: a loop) adds a transition between them.
  if (ImGui::IsItemActivated()) graph_drag_from_.reset();
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left) && !graph_drag_from_) {
    const ImVec2 start = ImGui::GetIO().MouseClickedPos[ImGuiMouseButton_Left];
    for (int s = 0; s < static_cast<int>(nodes.size()); ++s)
      if (std::hypot(start.x - nodes[s].x, start.y - nodes[s].y) <= node_radius) graph_drag_from_ = s;
  }
  if (graph_drag_from_) {
    const ImVec2 from = nodes[std::min<std::size_t>(*graph_drag_from_, nodes.size() - 1)];
    ImGui::GetWindowDrawList()->AddLine(from, mouse, IM_COL32(30, 90, 220, 200), 2);
    if (ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
      const int from_state = *graph_drag_from_, to_state = hit(nodes, node_radius);
      graph_drag_from_.reset();
      if (to_state >= 0) add_transition_between(from_state, to_state, scene::Choreography::kStraight);
    }
  }
  // Right-click: the menu of the node or badge under the mouse, else of the graph.
  if (ImGui::IsItemClicked(ImGuiMouseButton_Right)) {
    graph_menu_state_ = hit(nodes, node_radius);
    graph_menu_transition_ = graph_menu_state_ >= 0 ? -1 : hit(badges, 14);
    ImGui::OpenPopup("##graph menu");
  }
  if (!ImGui::BeginPopup("##graph menu")) return;
  const scene::Reconfigurable& scene = document_->scene();
  if (graph_menu_state_ >= 0 && graph_menu_state_ < static_cast<int>(scene.states.size())) {
    const std::string& name = scene.states[graph_menu_state_].name;
    ImGui::TextDisabled("state %s", name.c_str());
    if (ImGui::MenuItem("Show")) show_state(graph_menu_state_);
    if (ImGui::BeginMenu("Add transition to")) {
      for (int s = 0; s < static_cast<int>(scene.states.size()); ++s) {
        if (ImGui::MenuItem(fmt::format("{} (straight)", scene.states[s].name).c_str()))
          add_transition_between(graph_menu_state_, s, scene::Choreography::kStraight);
        if (ImGui::MenuItem(fmt::format("{} (screw)", scene.states[s].name).c_str()))
          add_transition_between(graph_menu_state_, s, scene::Choreography::kScrew);
      }
      ImGui::EndMenu();
    }
    if (ImGui::MenuItem("Rename..."))
      authoring_dialog_ = AuthoringDialog{.kind = Kind::kRenameState, .target = graph_menu_state_, .text = name};
    if (ImGui::MenuItem("Delete (with its transitions)", nullptr, false, scene.states.size() > 1))
      execute(scene::delete_state(name, true));
  } else if (graph_menu_transition_ >= 0 && graph_menu_transition_ < static_cast<int>(scene.transitions.size())) {
    const std::string& name = scene.transitions[graph_menu_transition_].name;
    ImGui::TextDisabled("transition %s", name.c_str());
    if (ImGui::MenuItem("Open")) open_transition(graph_menu_transition_);
    if (ImGui::MenuItem("Rename..."))
      authoring_dialog_ = AuthoringDialog{.kind = Kind::kRenameTransition, .target = graph_menu_transition_, .text = name};
    if (ImGui::MenuItem("Reverse")) execute(scene::reverse_transition(name));
    if (ImGui::MenuItem("Duplicate as an alternative..."))
      authoring_dialog_ =
          AuthoringDialog{.kind = Kind::kDuplicate, .target = graph_menu_transition_, .transition = true, .text = name + "_2"};
    if (ImGui::MenuItem("Delete")) execute(scene::delete_transition(name));
  } else {
    if (ImGui::MenuItem("Add state from the view..."))
      authoring_dialog_ = AuthoringDialog{.kind = Kind::kAddState, .text = fmt::format("state_{}", scene.states.size() + 1)};
    if (ImGui::MenuItem("Add transition..."))
      authoring_dialog_ = AuthoringDialog{.kind = Kind::kAddTransition, .from = active_state_, .to = active_state_};
  }
  ImGui::EndPopup();
}

}  // namespace reconfig::studio
