#include "reconfig/scene/collision_settings.h"

#include <cmath>

namespace reconfig::scene {

CollisionSettings CollisionSettings::overridden_by(const CollisionSettings& over) const {
  CollisionSettings merged = *this;
  if (over.tolerance) merged.tolerance = over.tolerance;
  if (over.dop) merged.dop = over.dop;
  if (over.box_resolution) merged.box_resolution = over.box_resolution;
  if (over.frame) merged.frame = over.frame;
  if (over.conservative) merged.conservative = over.conservative;
  if (over.contact) merged.contact = over.contact;
  if (over.touching_collides) merged.touching_collides = over.touching_collides;
  return merged;
}

std::string CollisionSettings::problem() const {
  if (tolerance && !(std::isfinite(*tolerance) && *tolerance > 0)) return "the tolerance must be a positive distance";
  if (dop && *dop != 8 && *dop != 28 && *dop != 80) return "the k-DOP family must have 8, 28 or 80 half-spaces";
  if (box_resolution && !(*box_resolution >= 0 && *box_resolution <= 1))
    return "the box grid must be between 0 (exact boxes) and 1 (a part's size)";
  if (frame && !(*frame > 0 && *frame <= 1)) return "a frame must last more than 0 and at most the whole transition";
  if (contact && !(std::isfinite(*contact) && *contact > 0)) return "the contact tolerance must be a positive distance";
  return "";
}

}  // namespace reconfig::scene
