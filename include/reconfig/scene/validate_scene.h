#pragma once
/// @file
/// Consistency rules of a design that the JSON grammar alone cannot express.

#include <string>

#include "reconfig/scene/reconfigurable.h"

namespace reconfig::scene {

/// Tolerances for "this key pose equals that state pose".
struct PoseTolerance {
  double translation = 1e-6;  ///< in scene units
  double rotation = 1e-4;     ///< radians
};

/// How far a position may lie from the origin, as a multiple of the design's size (the
/// largest coordinate of any part's mesh): beyond, the engine's absolute tolerances lose
/// their meaning (docs/file-formats.md, "Limits").
inline constexpr double kMaxCoordinateRatio = 1e6;

/// Checks names are unique and non-empty, states and tracks name existing parts, transitions
/// name existing states, every key time lies in [0, 1] and increases strictly, every
/// quaternion is unit, every number finite, every position (a pose's translation, a Bézier
/// point or handle, a part's center) within `kMaxCoordinateRatio` times the design's size of
/// the origin, each track's first and last keys equal the poses
/// of the transition's end states, a part without a track has the same pose in both, and the
/// collision settings are usable.
/// @throws InputError with the JSON path of the first problem (file left empty)
void validate_scene(const Reconfigurable& scene, const PoseTolerance& tolerance = {});

/// Whether two poses place a part identically within the tolerance.
bool poses_match(const motion::Pose& a, const motion::Pose& b, const PoseTolerance& tolerance = {});

}  // namespace reconfig::scene
