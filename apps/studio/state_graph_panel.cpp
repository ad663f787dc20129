#include "state_graph_panel.h"

#include <fmt/format.h>

#include <cmath>
#include <map>

#include "interval_kinds.h"
#include "panel_window.h"
#include "studio.h"

namespace reconfig::studio {
namespace {

constexpr float kLoopRadius = 14;

GraphGeometry graph_geometry(const scene::Reconfigurable& scene, ImVec2 min, ImVec2 max) {
  GraphGeometry geometry;
  const int states = static_cast<int>(scene.states.size());
  const ImVec2 center{(min.x + max.x) / 2, (min.y + max.y) / 2};
  const float radius = std::max(std::min(max.x - min.x, max.y - min.y) / 2 - 56, 10.0f);
  for (int s = 0; s < states; ++s) {
    const double angle = states == 1 ? 0 : M_PI + 2 * M_PI * s / states;
    geometry.nodes.push_back({center.x + (states == 1 ? 0 : radius * static_cast<float>(std::cos(angle))),
                              center.y + (states == 1 ? 0 : radius * static_cast<float>(std::sin(angle)))});
  }
  // Transitions between the same two states fan out to either side of the straight line.
  std::map<std::pair<int, int>, int> seen;
  for (const scene::Transition& transition : scene.transitions) {
    const int a = scene.find_state(transition.from), b = scene.find_state(transition.to);
    const ImVec2 pa = geometry.nodes[a], pb = geometry.nodes[b];
    const int k = seen[{std::min(a, b), std::max(a, b)}]++;
    if (a == b) {
      // A transition from a state to itself: a loop outside the node, the k-th one turned.
      const double angle = -M_PI / 2 + 0.9 * k;
      const float reach = geometry.node_radius + 2 * kLoopRadius;
      geometry.badges.push_back({pa.x + reach * static_cast<float>(std::cos(angle)),
                                 pa.y + reach * static_cast<float>(std::sin(angle))});
      continue;
    }
    const float side = (k % 2 == 0 ? 1.0f : -1.0f) * static_cast<float>((k + 1) / 2) * 26.0f * (a < b ? 1 : -1);
    const float dx = pb.x - pa.x, dy = pb.y - pa.y, length = std::max(std::sqrt(dx * dx + dy * dy), 1.0f);
    geometry.badges.push_back({(pa.x + pb.x) / 2 - dy / length * side, (pa.y + pb.y) / 2 + dx / length * side});
  }
  return geometry;
}

}  // namespace

std::optional<ImVec2> Studio::graph_edge_point(int transition) const {
  if (!document_ || transition < 0 || transition >= static_cast<int>(document_->scene().transitions.size()))
    return std::nullopt;
  return graph_geometry(document_->scene(), layout_.graph_min, layout_.graph_max).badges[transition];
}

std::optional<ImVec2> Studio::graph_state_point(int state) const {
  if (!document_ || state < 0 || state >= static_cast<int>(document_->scene().states.size())) return std::nullopt;
  return graph_geometry(document_->scene(), layout_.graph_min, layout_.graph_max).nodes[state];
}

void StateGraphPanel::draw(Studio& studio) {
  const PanelRects rects = current_panel_rects();
  begin_panel("State graph", rects.graph_pos, rects.graph_size);
  if (!studio.document_) {
    ImGui::End();
    return;
  }
  const ImVec2 min = ImGui::GetCursorScreenPos(), available = ImGui::GetContentRegionAvail();
  const ImVec2 max{min.x + available.x, min.y + available.y};
  studio.layout_.graph_min = min;
  studio.layout_.graph_max = max;
  const GraphGeometry geometry = graph_geometry(studio.document_->scene(), min, max);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw_edges(studio, draw, geometry);
  // Badges and labels after every edge, the labels on plates of the panel's colour: no edge is
  // drawn through a label.
  draw_badges(studio, draw, geometry);
  draw_nodes(studio, draw, geometry);
  ImGui::InvisibleButton("##graph", {std::max(available.x, 1.0f), std::max(available.y, 1.0f)});
  handle_clicks(studio, geometry);
  handle_authoring(studio, geometry);
  ImGui::End();
}

void StateGraphPanel::draw_edges(const Studio& studio, ImDrawList* draw, const GraphGeometry& geometry) const {
  const scene::Reconfigurable& scene = studio.document_->scene();
  for (int k = 0; k < static_cast<int>(scene.transitions.size()); ++k) {
    const scene::Transition& transition = scene.transitions[k];
    const ImVec2 a = geometry.nodes[scene.find_state(transition.from)], b = geometry.nodes[scene.find_state(transition.to)];
    const ImVec2 m = geometry.badges[k];
    const bool active = k == studio.active_transition_;
    const ImU32 color = active ? IM_COL32(30, 90, 220, 255) : IM_COL32(90, 90, 100, 255);
    if (transition.from == transition.to) {
      const float dx = m.x - a.x, dy = m.y - a.y, length = std::max(std::sqrt(dx * dx + dy * dy), 1.0f);
      const float to_center = length - kLoopRadius;
      draw->AddCircle({a.x + dx / length * to_center, a.y + dy / length * to_center}, kLoopRadius, color, 0,
                      active ? 3.0f : 1.5f);
    } else {
      draw->AddBezierQuadratic(a, {2 * m.x - (a.x + b.x) / 2, 2 * m.y - (a.y + b.y) / 2}, b, color,
                               active ? 3.0f : 1.5f);
    }
  }
}

void StateGraphPanel::draw_badges(const Studio& studio, ImDrawList* draw, const GraphGeometry& geometry) const {
  const scene::Reconfigurable& scene = studio.document_->scene();
  const auto snapshot = studio.collisions();
  const ImU32 plate = ImGui::GetColorU32(ImGuiCol_WindowBg);
  for (int k = 0; k < static_cast<int>(scene.transitions.size()); ++k) {
    const scene::Transition& transition = scene.transitions[k];
    const ImVec2 m = geometry.badges[k];
    // Collision badge.
    const collision::TransitionSnapshot* current = nullptr;
    if (snapshot)
      for (const auto& t : snapshot->transitions)
        if (t.transition == k) current = &t;
    const bool known = current && current->up_to_date && snapshot->version == studio.document_->version();
    // Red with the number of collisions; amber with the number of clearance intervals when
    // there are only those; green when free.
    const std::size_t clearances = current ? clearance_count(current->intervals) : 0;
    const std::size_t collisions = current ? current->intervals.size() - clearances : 0;
    const ImU32 fill = !known          ? IM_COL32(170, 170, 175, 255)
                       : collisions > 0 ? IM_COL32(215, 40, 30, 255)
                       : clearances > 0 ? IM_COL32(230, 165, 0, 255)
                                        : IM_COL32(60, 160, 80, 255);
    draw->AddCircleFilled(m, 11, fill);
    const std::string text = known ? fmt::format("{}", collisions > 0 ? collisions : clearances) : "...";
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    draw->AddText({m.x - size.x / 2, m.y - size.y / 2}, IM_COL32(255, 255, 255, 255), text.c_str());
    const ImVec2 name_size = ImGui::CalcTextSize(transition.name.c_str()), at{m.x + 14, m.y - name_size.y / 2};
    draw->AddRectFilled({at.x - 2, at.y - 1}, {at.x + name_size.x + 2, at.y + name_size.y + 1}, plate, 3);
    draw->AddText(at, k == studio.active_transition_ ? IM_COL32(20, 40, 110, 255) : IM_COL32(60, 60, 70, 255),
                  transition.name.c_str());
  }
}

void StateGraphPanel::draw_nodes(const Studio& studio, ImDrawList* draw, const GraphGeometry& geometry) const {
  const scene::Reconfigurable& scene = studio.document_->scene();
  for (int s = 0; s < static_cast<int>(scene.states.size()); ++s) {
    const ImVec2 p = geometry.nodes[s];
    const bool shown = studio.active_transition_ < 0 && s == studio.active_state_;
    draw->AddCircleFilled(p, geometry.node_radius, shown ? IM_COL32(200, 220, 255, 255) : IM_COL32(250, 250, 252, 255));
    draw->AddCircle(p, geometry.node_radius, IM_COL32(60, 60, 70, 255), 0, 2);
    const ImVec2 size = ImGui::CalcTextSize(scene.states[s].name.c_str());
    draw->AddText({p.x - size.x / 2, p.y + geometry.node_radius + 2}, IM_COL32(30, 30, 40, 255),
                  scene.states[s].name.c_str());
  }
}

void StateGraphPanel::handle_clicks(Studio& studio, const GraphGeometry& geometry) {
  if (!ImGui::IsItemClicked()) return;
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const auto near = [&](ImVec2 p, float r) { return std::hypot(mouse.x - p.x, mouse.y - p.y) <= r; };
  for (int k = 0; k < static_cast<int>(geometry.badges.size()); ++k)
    if (near(geometry.badges[k], 14)) studio.open_transition(k);
  for (int s = 0; s < static_cast<int>(geometry.nodes.size()); ++s)
    if (near(geometry.nodes[s], geometry.node_radius)) {
      studio.active_transition_ = -1;
      studio.active_state_ = s;
      studio.selected_key_.reset();
    }
}

}  // namespace reconfig::studio
