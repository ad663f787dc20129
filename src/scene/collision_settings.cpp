#include "reconfig/scene/collision_settings.h"

#include <cmath>

namespace reconfig::scene {

std::string dop_halfspace_choices() {
  std::string text;
  for (std::size_t i = 0; i < kDopHalfspaces.size(); ++i) {
    if (i > 0) text += i + 1 == kDopHalfspaces.size() ? " or " : ", ";
    text += std::to_string(kDopHalfspaces[i]);
  }
  return text;
}

CollisionSettings CollisionSettings::overridden_by(const CollisionSettings& over) const {
  CollisionSettings merged = *this;
  if (over.tolerance) merged.tolerance = over.tolerance;
  if (over.dop) merged.dop = over.dop;
  if (over.box_resolution) merged.box_resolution = over.box_resolution;
  if (over.frame) merged.frame = over.frame;
  if (over.conservative) merged.conservative = over.conservative;
  if (over.contact) merged.contact = over.contact;
  if (over.touching_collides) merged.touching_collides = over.touching_collides;
  if (over.clearance) merged.clearance = over.clearance;
  return merged;
}

std::string CollisionSettings::problem() const {
  if (tolerance && !(std::isfinite(*tolerance) && *tolerance > 0)) return "the tolerance must be a positive distance";
  if (dop && !is_dop_halfspace_count(*dop)) return "the k-DOP family must have " + dop_halfspace_choices() + " half-spaces";
  if (box_resolution && !(*box_resolution >= 0 && *box_resolution <= 1))
    return "the box grid must be between 0 (exact boxes) and 1 (a part's size)";
  if (frame && !(*frame > 0 && *frame <= 1)) return "a frame must last more than 0 and at most the whole transition";
  if (contact && !(std::isfinite(*contact) && *contact > 0)) return "the contact tolerance must be a positive distance";
  if (clearance && !(std::isfinite(*clearance) && *clearance >= 0)) return "the clearance must be a distance (0: none)";
  return "";
}

}  // namespace reconfig::scene
