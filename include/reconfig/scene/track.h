#pragma once
/// @file
/// How one part moves during a transition.

#include <Eigen/Core>
#include <optional>
#include <variant>
#include <vector>

#include "reconfig/motion/bezier_translation_track.h"
#include "reconfig/motion/pose.h"
#include "reconfig/motion/screw_track.h"
#include "reconfig/motion/slerp_rotation_track.h"

namespace reconfig::scene {

/// Keyframed motion (reconfigurables appendix): cubic Bézier translation keys and slerped
/// rotation keys, each on its own times. A missing list means that component holds still.
struct KeyframedTrack {
  std::vector<motion::TranslationKey> translation;
  std::vector<motion::RotationKey> rotation;

  bool operator==(const KeyframedTrack&) const = default;  ///< the same keys, bit for bit
};

/// Piecewise screw motion through key poses (Rossignac & Kim).
struct ScrewPosesTrack {
  std::vector<motion::ScrewKey> poses;

  bool operator==(const ScrewPosesTrack&) const = default;  ///< the same keys, bit for bit
};

using Track = std::variant<KeyframedTrack, ScrewPosesTrack>;

/// The pose a track gives at time t ∈ [0, 1] (clamped to the first/last key outside them).
/// @param hold    pose used for a component the track does not animate
/// @param center  the part's center of mass (screw motions act on the rigid map)
motion::Pose evaluate_track(const Track& track, double t, const motion::Pose& hold,
                            const Eigen::Vector3d& center);

/// The pose at the track's first (`at_end = false`) or last key.
motion::Pose track_end_pose(const Track& track, bool at_end, const motion::Pose& hold);

/// Sorted, unique times of every key of the track (translation, rotation or screw poses).
std::vector<double> key_times(const Track& track);

}  // namespace reconfig::scene
