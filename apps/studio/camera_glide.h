#pragma once
/// @file
/// A short camera flight from one orbit view to another (the jump to a collision's best view):
/// target, distance, yaw (the short way round) and pitch eased together.

#include "reconfig/view/camera.h"

namespace reconfig::studio {

struct CameraGlide {
  view::Camera from, to;
  double start = 0;       ///< seconds on the studio's clock
  double duration = 0.4;  ///< seconds

  /// The camera at `seconds`: `from` before the start, `to` from start + duration on, eased
  /// (smoothstep) in between; field of view and planes are `to`'s.
  view::Camera at(double seconds) const;
  bool done(double seconds) const { return seconds >= start + duration; }
};

}  // namespace reconfig::studio
