#pragma once
/// @file
/// Random reconfigurables for oracle tests: closed primitive parts tumbling along random
/// Bézier + slerp tracks (rotations up to a full turn).

#include <cstdint>

#include "reconfig/scene/reconfigurable.h"

namespace reconfig::testing {

struct RandomSceneOptions {
  int parts = 4;
  int moving = 3;           ///< how many of the parts move (the rest hold still)
  double spread = 0.8;      ///< positions are drawn in [−spread, spread]³
  double max_turn = 6.2832; ///< total rotation angle of a moving part (radians), up to a full turn
  int rotation_keys = 4;    ///< keys per rotation track (≥ 2; more allow turns beyond 180°)
  int sphere_subdivisions = 1;
  int cylinder_segments = 12;
};

/// A valid scene with one transition "move" from state "start" to "end".
scene::Reconfigurable random_scene(std::uint32_t seed, const RandomSceneOptions& options = {});

}  // namespace reconfig::testing
