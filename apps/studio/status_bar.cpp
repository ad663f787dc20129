#include "status_bar.h"

#include <algorithm>
#include <string>

#include "panel_window.h"
#include "studio.h"

namespace reconfig::studio {
namespace {

/// `text` cut to fit in `width` pixels, ending in "..." when cut.
std::string fitted(const std::string& text, float width) {
  if (ImGui::CalcTextSize(text.c_str()).x <= width) return text;
  std::size_t low = 0, high = text.size();
  while (low < high) {
    const std::size_t middle = (low + high + 1) / 2;
    if (ImGui::CalcTextSize((text.substr(0, middle) + "...").c_str()).x <= width) low = middle;
    else high = middle - 1;
  }
  while (low > 0 && (static_cast<unsigned char>(text[low]) & 0xC0) == 0x80) --low;  // not inside a character
  return text.substr(0, low) + "...";
}

}  // namespace

void StatusBar::message_changed(bool error) {
  window_open_ = false;
  window_due_ = error;
}

void StatusBar::draw(Studio& studio) {
  const ImGuiIO& io = ImGui::GetIO();
  const float height = status_bar_height();
  ImGui::SetNextWindowPos({0, io.DisplaySize.y - height});
  ImGui::SetNextWindowSize({io.DisplaySize.x, height});
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoBringToFrontOnFocus);
  const std::string line = studio.collision_summary();
  const std::string& status = studio.status();
  // The status gets the room left of the collision line; a longer one is cut, and its whole
  // text is a click away (an error opens it by itself).
  const float line_x = std::max(ImGui::GetWindowWidth() - ImGui::CalcTextSize(line.c_str()).x - 12, 300.0f);
  const float more_width = ImGui::CalcTextSize("more").x + 3 * ImGui::GetStyle().FramePadding.x;
  const std::string shown = fitted(status, line_x - ImGui::GetCursorPosX() - more_width - 16);
  if (studio.status_is_error()) ImGui::TextColored({0.8f, 0.1f, 0.1f, 1}, "%s", shown.c_str());
  else ImGui::TextUnformatted(shown.c_str());
  if (shown != status) {
    ImGui::SameLine();
    if (ImGui::SmallButton("more")) window_open_ = true;
    window_open_ = window_open_ || window_due_;
  }
  window_due_ = false;
  if (!line.empty()) {
    ImGui::SameLine(line_x);
    ImGui::TextUnformatted(line.c_str());
  }
  ImGui::End();
  draw_window(studio);
}

void StatusBar::draw_window(const Studio& studio) {
  if (!window_open_) return;
  const ImGuiIO& io = ImGui::GetIO();
  const std::string& status = studio.status();
  ImGui::SetNextWindowPos({io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f}, ImGuiCond_Appearing, {0.5f, 0.5f});
  ImGui::SetNextWindowSize({std::min(640.0f, io.DisplaySize.x - 40), 0}, ImGuiCond_Appearing);
  if (ImGui::Begin(studio.status_is_error() ? "Error" : "Message", &window_open_, ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::TextWrapped("%s", status.c_str());
    if (ImGui::Button("Copy")) ImGui::SetClipboardText(status.c_str());
    ImGui::SameLine();
    if (ImGui::Button("Close")) window_open_ = false;
  }
  ImGui::End();
}

}  // namespace reconfig::studio
