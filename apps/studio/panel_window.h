#pragma once
/// @file
/// The studio's fixed panel arrangement: every panel is an undecorated ImGui window at a
/// place computed from the display size, so the layout is the same in a window, headless and
/// in tests.

#include <imgui.h>

namespace reconfig::studio {

/// Rectangles of the panels for a display of `size` pixels, below a menu bar `menu` pixels
/// high and above a status bar `status` pixels high.
struct PanelRects {
  ImVec2 graph_pos, graph_size;
  ImVec2 inspector_pos, inspector_size;
  ImVec2 viewport_pos, viewport_size;
  ImVec2 timeline_pos, timeline_size;
};
PanelRects panel_rects(ImVec2 size, float menu, float status);

/// Height of the status bar at the bottom.
float status_bar_height();
/// The rectangles for the current ImGui frame (display size, main menu bar, status bar).
PanelRects current_panel_rects();

/// Begins a panel window at that place (always call ImGui::End() after). Without padding the
/// window has no background either: its content (the viewport image) covers all of it.
bool begin_panel(const char* name, ImVec2 pos, ImVec2 size, bool padding = true);

}  // namespace reconfig::studio
