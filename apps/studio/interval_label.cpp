#include "interval_label.h"

#include <fmt/format.h>
#include <imgui.h>

#include "fit_text.h"

namespace reconfig::studio {

std::string interval_label(double t0, double t1, const std::vector<std::string>& parts, float width) {
  std::string label = fmt::format("{:.3f}-{:.3f}", t0, t1), line;
  for (const std::string& part : parts) {
    const std::string joined = line.empty() ? part : line + " × " + part;
    if (line.empty() || ImGui::CalcTextSize(joined.c_str()).x <= width) {
      line = joined;
      continue;
    }
    label.append("\n").append(fit_text(line, width));  // (appended: `"\n" + …` gets GCC 12's false -Wrestrict)
    line = std::string("× ").append(part);
  }
  if (!line.empty()) label.append("\n").append(fit_text(line, width));
  return label;
}

}  // namespace reconfig::studio
