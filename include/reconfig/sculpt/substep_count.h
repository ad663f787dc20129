#pragma once
/// @file
/// How many sub-steps a stroke needs so that none folds space over (Sweepers eq. 1 and 3,
/// §4.1–4.3).

#include <vector>

#include "reconfig/sculpt/tool.h"
#include "reconfig/sculpt/tool_motion.h"

namespace reconfig::sculpt {

/// A tool and the path it follows during a stroke.
struct MovingTool {
  Tool tool;          ///< where the tool is when the stroke starts
  ToolMotion motion;  ///< its relative transformation M over the stroke
};

/// The bound of eq. (3), Σ_j (1.875 / λ_j) · max_k ‖(log M_j) p_kj‖, over the corners p_kj of
/// the tool's field box at the start and at the end of the stroke (the box moves: taking both
/// keeps the bound for every sub-step). For one tool it is eq. (1), which reduces to
/// 1.875‖d‖/λ for a translation (§4.1), 1.875 |log σ| S_max / λ for a scaling (§4.2) and
/// 1.875 |θ| R_max / λ for a rotation (§4.3), S_max and R_max measured from those corners.
/// @param tools  the tools moving together (n ≥ 1)
double foldover_bound(const std::vector<MovingTool>& tools);

/// The least number of sub-steps s with s > `foldover_bound(tools)` (at least 1).
int substep_count(const std::vector<MovingTool>& tools);

}  // namespace reconfig::sculpt
