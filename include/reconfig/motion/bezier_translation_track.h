#pragma once
/// @file
/// Keyframed translation along a piecewise cubic Bézier curve (reconfigurables paper,
/// eq. 11–15).

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <vector>

namespace reconfig::motion {

/// One translational keyframe: at time `time` the translation passes through `point`
/// (t_j); `in` (u_j) and `out` (w_j) are its incoming and outgoing Bézier handles, given as
/// absolute positions (not offsets from the point), as in the scene file.
struct TranslationKey {
  double time = 0.0;                               ///< s_j
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< t_j
  Eigen::Vector3d in = Eigen::Vector3d::Zero();     ///< u_j, handle before the key
  Eigen::Vector3d out = Eigen::Vector3d::Zero();    ///< w_j, handle after the key

  bool operator==(const TranslationKey&) const = default;  ///< the same numbers, bit for bit
};

/// The translation x(t) of a part: between keys j and j+1, with f = (t − s_j)/(s_{j+1} − s_j),
/// `x = (1−f)³ t_j + 3(1−f)² f w_j + 3(1−f) f² u_{j+1} + f³ t_{j+1}`.
/// Before the first key x is the first point, after the last key the last point; a single
/// key gives a constant. The `in` handle of the first key and the `out` handle of the last
/// key are stored but do not influence the curve.
class BezierTranslationTrack {
 public:
  /// @param keys  at least one key, times finite and strictly increasing, all vectors finite
  /// @throws KeyError naming the first offending key and field
  explicit BezierTranslationTrack(std::vector<TranslationKey> keys);

  /// Throws `KeyError` if `keys` cannot make a track (see the constructor); returns otherwise.
  static void validate(const std::vector<TranslationKey>& keys);

  /// x(t), clamped to the first/last point outside [start_time(), end_time()].
  Eigen::Vector3d evaluate(double t) const;

  /// Velocity dx/dt (per unit of time). Zero outside (start_time(), end_time()); at a key
  /// time inside the track it is the right-hand derivative (the segment that starts there).
  Eigen::Vector3d derivative(double t) const;

  const std::vector<TranslationKey>& keys() const { return keys_; }
  /// The key times s_0 < s_1 < ..., in key order.
  const std::vector<double>& key_times() const { return times_; }
  double start_time() const { return keys_.front().time; }
  double end_time() const { return keys_.back().time; }
  /// Number of Bézier segments: keys().size() − 1.
  std::size_t segment_count() const { return keys_.size() - 1; }

  /// The Bézier control points of segment j (0 <= j < segment_count()):
  /// {t_j, w_j, u_{j+1}, t_{j+1}}.
  std::array<Eigen::Vector3d, 4> control_points(std::size_t j) const;

 private:
  std::vector<TranslationKey> keys_;
  std::vector<double> times_;
};

}  // namespace reconfig::motion
