#pragma once
/// @file
/// Collisions > Settings: a small window that edits how the collision service detects
/// (tolerance, k-DOP family, box grid, frame length, conservative mode, contact tolerance,
/// touching, clearance); its Apply button hands them to Studio::set_detector_options. Its own
/// state (the settings being edited, while it is open), drawn by `draw` (like pip_panel.h).

#include <optional>

#include "reconfig/collision/spacetime_detector.h"

namespace reconfig::studio {

class Studio;

class CollisionSettingsWindow {
 public:
  /// Opens it on the studio's settings now.
  void show(const Studio& studio);
  void draw(Studio& studio);

 private:
  std::optional<collision::DetectorOptions> draft_;  ///< the settings being edited, while open
};

}  // namespace reconfig::studio
