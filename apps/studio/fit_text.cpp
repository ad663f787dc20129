#include "fit_text.h"

#include <imgui.h>

namespace reconfig::studio {

std::string fit_text(const std::string& text, float width) {
  if (ImGui::CalcTextSize(text.c_str()).x <= width) return text;
  for (std::size_t keep = text.size(); keep-- > 0;) {
    const std::string cut = text.substr(0, keep) + "...";
    if (ImGui::CalcTextSize(cut.c_str()).x <= width) return cut;
  }
  return "...";
}

}  // namespace reconfig::studio
