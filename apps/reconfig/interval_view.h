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

/// The camera of a picture of the interval: the view's eye and target with a wider field of
/// view (1.2 rad instead of 0.7: the parts around the box too, and no new occluder, as the eye
/// stays where the counts were made), its far plane beyond all of `scene_bounds`.
view::Camera picture_camera(const render::BestView& view, const Eigen::AlignedBox3d& scene_bounds);

/// `{"eye": [..], "center": [..], "up": [..], "visible_fraction": f}` (docs/file-formats.md).
nlohmann::ordered_json view_json(const render::BestView& view);

}  // namespace reconfig::cli
