#include "reconfig/collision/detector_settings.h"

#include <cassert>

namespace reconfig::collision {

DetectorOptions with_settings(DetectorOptions base, const scene::CollisionSettings& settings) {
  assert(settings.problem().empty());
  if (settings.tolerance) base.tolerance = *settings.tolerance;
  if (settings.dop) base.dop = dop_family(*settings.dop).value_or(base.dop);
  if (settings.box_resolution) base.box_resolution = *settings.box_resolution;
  if (settings.frame) base.frame = *settings.frame;
  if (settings.conservative) base.conservative = *settings.conservative;
  if (settings.contact) base.contact = *settings.contact;
  if (settings.touching_collides) base.touching_collides = *settings.touching_collides;
  if (settings.clearance) base.clearance = *settings.clearance;
  return base;
}

scene::CollisionSettings settings_of(const DetectorOptions& options) {
  return {.tolerance = options.tolerance,
          .dop = halfspace_count(options.dop),
          .box_resolution = options.box_resolution,
          .frame = options.frame,
          .conservative = options.conservative,
          .contact = options.contact > 0 ? std::optional(options.contact) : std::nullopt,  // unset: the design's default
          .touching_collides = options.touching_collides,
          .clearance = options.clearance > 0 ? std::optional(options.clearance) : std::nullopt};
}

}  // namespace reconfig::collision
