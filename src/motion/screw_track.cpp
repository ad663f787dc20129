#include "reconfig/motion/screw_track.h"

#include "motion/detail/key_times.h"
#include "reconfig/motion/key_error.h"

#include <cmath>
#include <utility>

namespace reconfig::motion {

using detail::KeyLocation;

void ScrewTrack::validate(const std::vector<ScrewKey>& keys) {
  if (keys.empty()) throw KeyError(0, "", "a screw track needs at least one key pose");
  for (std::size_t j = 0; j < keys.size(); ++j) {
    const ScrewKey& k = keys[j];
    if (!std::isfinite(k.time)) throw KeyError(j, "time", "time is not a finite number");
    if (j > 0 && !(k.time > keys[j - 1].time))
      throw KeyError(j, "time", "keyframe times must strictly increase");
    if (!k.pose.translation.allFinite())
      throw KeyError(j, "translation", "translation is not finite");
    if (!k.pose.rotation.coeffs().allFinite())
      throw KeyError(j, "rotation", "quaternion is not finite");
    if (!(k.pose.rotation.norm() > 1e-12))
      throw KeyError(j, "rotation", "quaternion has zero length");
  }
}

ScrewTrack::ScrewTrack(std::vector<ScrewKey> keys, const Eigen::Vector3d& center)
    : keys_(std::move(keys)), center_(center) {
  validate(keys_);
  times_.reserve(keys_.size());
  for (ScrewKey& k : keys_) {
    k.pose.rotation.normalize();
    times_.push_back(k.time);
  }
  screws_.reserve(keys_.size() - 1);
  for (std::size_t j = 0; j + 1 < keys_.size(); ++j)
    screws_.emplace_back(keys_[j].pose.to_isometry(center_),
                         keys_[j + 1].pose.to_isometry(center_));
}

Eigen::Isometry3d ScrewTrack::at(double t) const {
  const KeyLocation loc = detail::locate(times_, t);
  if (loc.region != KeyLocation::Region::kInside)
    return keys_[loc.segment].pose.to_isometry(center_);
  return screws_[loc.segment].at(loc.f);
}

Pose ScrewTrack::evaluate(double t) const {
  const KeyLocation loc = detail::locate(times_, t);
  if (loc.region != KeyLocation::Region::kInside || loc.f == 0.0)
    return keys_[loc.segment].pose;
  return Pose::from_isometry(screws_[loc.segment].at(loc.f), center_);
}

}  // namespace reconfig::motion
