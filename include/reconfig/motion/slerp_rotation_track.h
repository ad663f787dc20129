#pragma once
/// @file
/// Keyframed rotation by spherical linear interpolation of unit quaternions
/// (reconfigurables paper, eq. 24–25).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <vector>

namespace reconfig::motion {

/// One rotational keyframe: at time `time` the part has rotation `rotation` (θ_j) about its
/// center. The constructor normalizes the quaternion.
struct RotationKey {
  double time = 0.0;                                                 ///< σ_j
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  ///< θ_j

  /// The same numbers, bit for bit (q and −q differ).
  bool operator==(const RotationKey& other) const {
    return time == other.time && rotation.coeffs() == other.rotation.coeffs();
  }
};

/// The rotation θ(t): between keys j and j+1, with g = (t − σ_j)/(σ_{j+1} − σ_j),
/// `θ(g) = θ_j (θ_j⁻¹ θ_{j+1})^g` taken along the shortest arc: if θ_j·θ_{j+1} < 0 the
/// second quaternion is negated first (so exactly opposite quaternions, which are the same
/// rotation, give a constant rotation). When the two keys are exactly 180° apart
/// (θ_j·θ_{j+1} = 0) both arcs are equally short and the signs of the stored quaternions
/// decide: the motion turns about the vector part of θ_j⁻¹ θ_{j+1}. Computed through the
/// rotation vector of θ_j⁻¹ θ_{j+1}, so nearly identical keys are handled without division
/// by a vanishing sine. Clamped outside [start_time(), end_time()]; one key = constant.
class SlerpRotationTrack {
 public:
  /// @param keys  at least one key, times finite and strictly increasing, quaternions
  ///              finite with norm > 1e-12 (they are normalized)
  /// @throws KeyError naming the first offending key and field (`time` or `quaternion`)
  explicit SlerpRotationTrack(std::vector<RotationKey> keys);

  /// Throws `KeyError` if `keys` cannot make a track (see the constructor); returns otherwise.
  static void validate(const std::vector<RotationKey>& keys);

  /// θ(t) as a unit quaternion.
  Eigen::Quaterniond evaluate(double t) const;

  /// World-frame angular velocity ω(t) (dR/dt = [ω]× R), in radians per unit time. Zero
  /// outside (start_time(), end_time()); right-hand value at a key time.
  Eigen::Vector3d angular_velocity(double t) const;

  /// The keys, quaternions normalized.
  const std::vector<RotationKey>& keys() const { return keys_; }
  /// The key times s_0 < s_1 < ..., in key order.
  const std::vector<double>& key_times() const { return times_; }
  double start_time() const { return keys_.front().time; }
  double end_time() const { return keys_.back().time; }
  /// Number of slerp segments: keys().size() − 1.
  std::size_t segment_count() const { return keys_.size() - 1; }

  /// Rotation vector φ_j of segment j in the frame of key j: θ_j⁻¹ θ_{j+1} (shortest arc) =
  /// exp(φ_j); |φ_j| ∈ [0, π] is the angle the segment turns through.
  const Eigen::Vector3d& segment_rotation_vector(std::size_t j) const { return phi_[j]; }

 private:
  std::vector<RotationKey> keys_;
  std::vector<double> times_;
  std::vector<Eigen::Vector3d> phi_;
};

}  // namespace reconfig::motion
