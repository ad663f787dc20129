#pragma once
/// @file
/// Whether a tolerance suits a design's size: the proxies' time steps follow an absolute
/// tolerance, so a part ten million times larger than it needs steps beyond any budget (a part
/// 1e7 long at 1 mm: 34 s and 0.9 GB; 1e10: minutes).

#include <string>
#include <vector>

#include "reconfig/scene/reconfigurable.h"

namespace reconfig::collision {

/// The largest ratio of a moving part's radius to the tolerance detection accepts
/// (docs/file-formats.md, "Limits"): 1e5 at 1 mm takes under a second.
inline constexpr double kMaxSizeToTolerance = 1e8;

/// Why `tolerance` is too fine for the parts that move in `transitions` (all if empty) — the
/// largest such part's radius around its center is more than `kMaxSizeToTolerance` times
/// the tolerance — or "" if it is not.
std::string tolerance_scale_problem(const scene::Reconfigurable& scene, const std::vector<int>& transitions,
                                    double tolerance);

}  // namespace reconfig::collision
