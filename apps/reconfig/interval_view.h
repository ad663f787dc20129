#pragma once
/// @file
/// The view-optimized camera of one collision interval at its severity time (reconfigurables
/// §4.3), shared by `check --views`, `check --report DIR/` and `render --interval K --best-view`.

#include <nlohmann/json.hpp>

#include "reconfig/collision/collision_interval.h"
#include "reconfig/render/best_view.h"
#include "reconfig/scene/reconfigurable.h"

namespace reconfig::cli {

/// The best view of `interval` of transition `transition` seen at time `time`. Needs a current
/// OpenGL context (the counter's).
render::BestView interval_best_view(render::OcclusionCounter& counter, const scene::Reconfigurable& scene,
                                    int transition, const collision::CollisionInterval& interval, double time);

/// `{"eye": [..], "center": [..], "up": [..], "visible_fraction": f}` (docs/file-formats.md).
nlohmann::ordered_json view_json(const render::BestView& view);

}  // namespace reconfig::cli
