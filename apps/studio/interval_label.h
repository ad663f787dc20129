#pragma once
/// @file
/// The inspector's entry for a collision interval: its times, then the parts it names, broken
/// into lines that fit the panel, so no part name is cut ("cabinet_door_left × pullout_s").

#include <string>
#include <vector>

namespace reconfig::studio {

/// "0.023-0.497" on the first line, then the part names joined by " × ", a new line (starting
/// "× ") wherever the next name would not fit in `width` pixels of the current ImGui font; a
/// name too wide for a line of its own is cut with "..." (fit_text). Needs an ImGui context.
std::string interval_label(double t0, double t1, const std::vector<std::string>& parts, float width);

}  // namespace reconfig::studio
