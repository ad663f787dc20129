#pragma once
/// @file
/// Piecewise screw motion through key poses (Rossignac & Kim).

#include "reconfig/motion/pose.h"
#include "reconfig/motion/screw_motion.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <vector>

namespace reconfig::motion {

/// A key pose: at time `time` the part is at `pose` (about the track's center).
struct ScrewKey {
  double time = 0.0;
  Pose pose;

  bool operator==(const ScrewKey&) const = default;  ///< the same numbers, bit for bit
};

/// The motion of a part through key poses, consecutive poses joined by `ScrewMotion`s.
///
/// Design: the track stores the part's center c. A `Pose` only becomes a rigid map once c
/// is known (`Pose::to_isometry(c)`), and the screw between two rigid maps is intrinsic, so
/// the screws are computed once at construction. If the part's center changes (its mesh
/// was edited), build a new track.
///
/// Between keys j and j+1, with f = (t − s_j)/(s_{j+1} − s_j), the part is at
/// `ScrewMotion(K_j, K_{j+1}).at(f)`, K_j = keys[j].pose.to_isometry(center). At a key time
/// it is exactly at the key pose; before the first / after the last key it holds the
/// first / last pose; a single key is a constant pose.
class ScrewTrack {
 public:
  /// @param keys    at least one key, times finite and strictly increasing, translations
  ///                finite, quaternions finite with norm > 1e-12 (they are normalized)
  /// @param center  the part's center c (#3), used to turn poses into rigid maps
  /// @throws KeyError naming the first offending key and field (`time`, `translation`,
  ///         `rotation`)
  ScrewTrack(std::vector<ScrewKey> keys, const Eigen::Vector3d& center);

  /// Throws `KeyError` if `keys` cannot make a track; returns otherwise.
  static void validate(const std::vector<ScrewKey>& keys);

  /// The pose at time t, about center().
  Pose evaluate(double t) const;

  /// The rigid map at time t: rest point p goes to `at(t) * p`.
  Eigen::Isometry3d at(double t) const;

  /// The keys, quaternions normalized.
  const std::vector<ScrewKey>& keys() const { return keys_; }
  const Eigen::Vector3d& center() const { return center_; }
  /// The key times s_0 < s_1 < ..., in key order.
  const std::vector<double>& key_times() const { return times_; }
  double start_time() const { return keys_.front().time; }
  double end_time() const { return keys_.back().time; }
  /// Number of screw segments: keys().size() − 1.
  std::size_t segment_count() const { return screws_.size(); }
  /// Screw j, from key j (at its parameter 0) to key j+1 (parameter 1).
  const ScrewMotion& segment(std::size_t j) const { return screws_[j]; }

 private:
  std::vector<ScrewKey> keys_;
  std::vector<double> times_;
  std::vector<ScrewMotion> screws_;
  Eigen::Vector3d center_;
};

}  // namespace reconfig::motion
