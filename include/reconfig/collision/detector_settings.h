#pragma once
/// @file
/// Between a design's saved collision settings and the detector's options.

#include "reconfig/collision/spacetime_detector.h"
#include "reconfig/scene/collision_settings.h"

namespace reconfig::collision {

/// `base` with each setting that `settings` sets (which must be usable: `settings.problem()`
/// empty).
DetectorOptions with_settings(DetectorOptions base, const scene::CollisionSettings& settings);

/// Every setting of `options` that a design saves.
scene::CollisionSettings settings_of(const DetectorOptions& options);

}  // namespace reconfig::collision
