// The state graph's authoring: right-click menus of a node, a badge or the graph, and drags
// from one node to another (or the same one: a loop) that add a transition between them. Each
// item ends in one of the studio's authoring actions (authoring.cpp), a scene command, or an
// authoring dialog (authoring_menu.h).

#include <fmt/format.h>

#include <cmath>

#include "reconfig/scene/state_edits.h"
#include "state_graph_panel.h"
#include "studio.h"

namespace reconfig::studio {
namespace {

using Kind = AuthoringDialog::Kind;

/// The point of `points` within `radius` of `at`, or −1.
int hit(const std::vector<ImVec2>& points, float radius, ImVec2 at) {
  for (int k = 0; k < static_cast<int>(points.size()); ++k)
    if (std::hypot(at.x - points[k].x, at.y - points[k].y) <= radius) return k;
  return -1;
}

}  // namespace

void StateGraphPanel::handle_authoring(Studio& studio, const GraphGeometry& geometry) {
  handle_drag(studio, geometry);
  // Right-click: the menu of the node or badge under the mouse, else of the graph.
  if (ImGui::IsItemClicked(ImGuiMouseButton_Right)) {
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    menu_state_ = hit(geometry.nodes, geometry.node_radius, mouse);
    menu_transition_ = menu_state_ >= 0 ? -1 : hit(geometry.badges, 14, mouse);
    ImGui::OpenPopup("##graph menu");
  }
  if (!ImGui::BeginPopup("##graph menu")) return;
  const scene::Reconfigurable& scene = studio.document()->scene();
  if (menu_state_ >= 0 && menu_state_ < static_cast<int>(scene.states.size())) draw_state_menu(studio, menu_state_);
  else if (menu_transition_ >= 0 && menu_transition_ < static_cast<int>(scene.transitions.size()))
    draw_transition_menu(studio, menu_transition_);
  else draw_graph_menu(studio);
  ImGui::EndPopup();
}

void StateGraphPanel::handle_drag(Studio& studio, const GraphGeometry& geometry) {
  const std::vector<ImVec2>& nodes = geometry.nodes;
  if (ImGui::IsItemActivated()) drag_from_.reset();
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left) && !drag_from_) {
    const ImVec2 start = ImGui::GetIO().MouseClickedPos[ImGuiMouseButton_Left];
    for (int s = 0; s < static_cast<int>(nodes.size()); ++s)
      if (std::hypot(start.x - nodes[s].x, start.y - nodes[s].y) <= geometry.node_radius) drag_from_ = s;
  }
  if (!drag_from_) return;
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const ImVec2 from = nodes[std::min<std::size_t>(*drag_from_, nodes.size() - 1)];
  ImGui::GetWindowDrawList()->AddLine(from, mouse, IM_COL32(30, 90, 220, 200), 2);
  if (ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
    const int from_state = *drag_from_, to_state = hit(nodes, geometry.node_radius, mouse);
    drag_from_.reset();
    if (to_state >= 0) studio.add_transition_between(from_state, to_state, scene::Choreography::kStraight);
  }
}

void StateGraphPanel::draw_state_menu(Studio& studio, int state) {
  const scene::Reconfigurable& scene = studio.document()->scene();
  const std::string& name = scene.states[state].name;
  ImGui::TextDisabled("state %s", name.c_str());
  if (ImGui::MenuItem("Show")) studio.show_state(state);
  if (ImGui::BeginMenu("Add transition to")) {
    for (int s = 0; s < static_cast<int>(scene.states.size()); ++s) {
      if (ImGui::MenuItem(fmt::format("{} (straight)", scene.states[s].name).c_str()))
        studio.add_transition_between(state, s, scene::Choreography::kStraight);
      if (ImGui::MenuItem(fmt::format("{} (screw)", scene.states[s].name).c_str()))
        studio.add_transition_between(state, s, scene::Choreography::kScrew);
    }
    ImGui::EndMenu();
  }
  if (ImGui::MenuItem("Rename..."))
    studio.open_authoring_dialog(AuthoringDialog{.kind = Kind::kRenameState, .target = state, .text = name});
  if (ImGui::MenuItem("Delete (with its transitions)", nullptr, false, scene.states.size() > 1))
    studio.execute(scene::delete_state(name, true));
}

void StateGraphPanel::draw_transition_menu(Studio& studio, int transition) {
  const std::string& name = studio.document()->scene().transitions[transition].name;
  ImGui::TextDisabled("transition %s", name.c_str());
  if (ImGui::MenuItem("Open")) studio.open_transition(transition);
  if (ImGui::MenuItem("Rename..."))
    studio.open_authoring_dialog(AuthoringDialog{.kind = Kind::kRenameTransition, .target = transition, .text = name});
  if (ImGui::MenuItem("Reverse")) studio.execute(scene::reverse_transition(name));
  if (ImGui::MenuItem("Duplicate as an alternative..."))
    studio.open_authoring_dialog(
        AuthoringDialog{.kind = Kind::kDuplicate, .target = transition, .transition = true, .text = name + "_2"});
  if (ImGui::MenuItem("Delete")) studio.execute(scene::delete_transition(name));
}

void StateGraphPanel::draw_graph_menu(Studio& studio) {
  const std::size_t states = studio.document()->scene().states.size();
  const int shown = studio.active_state_;
  if (ImGui::MenuItem("Add state from the view..."))
    studio.open_authoring_dialog(AuthoringDialog{.kind = Kind::kAddState, .text = fmt::format("state_{}", states + 1)});
  if (ImGui::MenuItem("Add transition..."))
    studio.open_authoring_dialog(AuthoringDialog{.kind = Kind::kAddTransition, .from = shown, .to = shown});
}

}  // namespace reconfig::studio
