#include "reconfig/motion/slerp_rotation_track.h"

#include "motion/detail/key_times.h"
#include "motion/detail/so3.h"
#include "reconfig/motion/key_error.h"

#include <cmath>
#include <utility>

namespace reconfig::motion {

using detail::KeyLocation;

void SlerpRotationTrack::validate(const std::vector<RotationKey>& keys) {
  if (keys.empty()) throw KeyError(0, "", "a rotation track needs at least one key");
  for (std::size_t j = 0; j < keys.size(); ++j) {
    const RotationKey& k = keys[j];
    if (!std::isfinite(k.time)) throw KeyError(j, "time", "time is not a finite number");
    if (j > 0 && !(k.time > keys[j - 1].time))
      throw KeyError(j, "time", "keyframe times must strictly increase");
    if (!k.rotation.coeffs().allFinite())
      throw KeyError(j, "quaternion", "quaternion is not finite");
    if (!(k.rotation.norm() > 1e-12))
      throw KeyError(j, "quaternion", "quaternion has zero length");
  }
}

SlerpRotationTrack::SlerpRotationTrack(std::vector<RotationKey> keys) : keys_(std::move(keys)) {
  validate(keys_);
  times_.reserve(keys_.size());
  for (RotationKey& k : keys_) {
    k.rotation.normalize();
    times_.push_back(k.time);
  }
  phi_.reserve(keys_.size() - 1);
  for (std::size_t j = 0; j + 1 < keys_.size(); ++j) {
    Eigen::Quaterniond r = keys_[j].rotation.conjugate() * keys_[j + 1].rotation;
    // Shortest arc; at exactly 180° (w == 0) the stored signs decide (quat_log keeps them).
    if (r.w() < 0.0) r.coeffs() = -r.coeffs();
    phi_.push_back(detail::quat_log(r));
  }
}

Eigen::Quaterniond SlerpRotationTrack::evaluate(double t) const {
  const KeyLocation loc = detail::locate(times_, t);
  if (loc.region != KeyLocation::Region::kInside) return keys_[loc.segment].rotation;
  const std::size_t j = loc.segment;
  return (keys_[j].rotation * detail::quat_exp(loc.f * phi_[j])).normalized();
}

Eigen::Vector3d SlerpRotationTrack::angular_velocity(double t) const {
  const KeyLocation loc = detail::locate(times_, t);
  if (loc.region != KeyLocation::Region::kInside) return Eigen::Vector3d::Zero();
  const std::size_t j = loc.segment;
  // dθ/dg = θ(g) (0, φ/2): body rate φ per unit g, the same vector in key j's frame.
  return (keys_[j].rotation * phi_[j]) / (times_[j + 1] - times_[j]);
}

}  // namespace reconfig::motion
