#include "panel_window.h"

#include <algorithm>

namespace reconfig::studio {

PanelRects panel_rects(ImVec2 size, float menu, float status) {
  const float left = std::clamp(size.x * 0.24f, 220.0f, 340.0f);
  const float timeline = std::clamp(size.y * 0.26f, 176.0f, 230.0f);
  const float body = std::max(size.y - menu - status, 1.0f);
  const float graph = body * 0.42f;
  PanelRects rects;
  rects.graph_pos = {0, menu};
  rects.graph_size = {left, graph};
  rects.inspector_pos = {0, menu + graph};
  rects.inspector_size = {left, body - graph};
  rects.viewport_pos = {left, menu};
  rects.viewport_size = {std::max(size.x - left, 1.0f), std::max(body - timeline, 1.0f)};
  rects.timeline_pos = {left, menu + rects.viewport_size.y};
  rects.timeline_size = {rects.viewport_size.x, timeline};
  return rects;
}

float status_bar_height() { return ImGui::GetFrameHeight() + 4; }

PanelRects current_panel_rects() {
  return panel_rects(ImGui::GetIO().DisplaySize, ImGui::GetFrameHeight(), status_bar_height());
}

bool begin_panel(const char* name, ImVec2 pos, ImVec2 size, bool padding) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  if (!padding) ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {0, 0});
  const bool open = ImGui::Begin(name, nullptr,
                                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus |
                                     (padding ? 0
                                              : ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse |
                                                    ImGuiWindowFlags_NoBackground));
  if (!padding) ImGui::PopStyleVar();
  return open;
}

}  // namespace reconfig::studio
