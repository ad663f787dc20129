#pragma once
/// @file
/// The resolution hint on screen (resolve_panel.h computes and draws it; the viewport, the
/// timeline and the inspector show it): the design version it is for, its part and result.

#include <cstdint>

#include "reconfig/resolve/hints.h"
#include "reconfig/scene/track.h"

namespace reconfig::studio {

struct HintView {
  int transition = -1, part = -1;
  std::uint64_t version = 0;
  resolve::HintResult result;
  int steepest = -1;                  ///< index in result.hints, −1 when none
  scene::KeyframedTrack base;         ///< the part's track when the hint was given
  double slide = 0;                   ///< the slider's position
  bool sliding = false;               ///< a slide's edit is applied and may be replaced
};

}  // namespace reconfig::studio
