#pragma once
/// @file
/// The state graph: states as nodes on a circle, transitions as arrows with a collision badge
/// (count of maximal intervals; grey while being detected). Clicking a badge or edge opens the
/// transition's timeline; clicking a state shows it. Right-click menus and node-to-node drags
/// author states and transitions (state_graph_menu.cpp). Its own state (a drag from a node, what
/// the right-click menu is for), drawn by `draw` (like pip_panel.h); where its nodes and badges
/// are is Studio::graph_state_point and Studio::graph_edge_point.

#include <imgui.h>

#include <optional>
#include <vector>

namespace reconfig::studio {

class Studio;

/// Where the state graph's nodes and badges are drawn.
struct GraphGeometry {
  std::vector<ImVec2> nodes;   ///< per state
  std::vector<ImVec2> badges;  ///< per transition
  float node_radius = 18;
};

class StateGraphPanel {
 public:
  void draw(Studio& studio);

 private:
  void draw_edges(const Studio& studio, ImDrawList* draw, const GraphGeometry& geometry) const;
  void draw_badges(const Studio& studio, ImDrawList* draw, const GraphGeometry& geometry) const;
  void draw_nodes(const Studio& studio, ImDrawList* draw, const GraphGeometry& geometry) const;
  /// Clicks on the graph (its invisible button is the last item): open a transition, show a state.
  void handle_clicks(Studio& studio, const GraphGeometry& geometry);
  /// Right-click menus and node-to-node drags (state_graph_menu.cpp).
  void handle_authoring(Studio& studio, const GraphGeometry& geometry);
  void handle_drag(Studio& studio, const GraphGeometry& geometry);
  void draw_state_menu(Studio& studio, int state);
  void draw_transition_menu(Studio& studio, int transition);
  void draw_graph_menu(Studio& studio);

  std::optional<int> drag_from_;                  ///< a drag from this state's node
  int menu_state_ = -1, menu_transition_ = -1;    ///< what the right-click menu is for
};

}  // namespace reconfig::studio
