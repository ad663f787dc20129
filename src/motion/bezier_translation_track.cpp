#include "reconfig/motion/bezier_translation_track.h"

#include "motion/detail/key_times.h"
#include "reconfig/motion/key_error.h"

#include <cmath>
#include <utility>

namespace reconfig::motion {

using detail::KeyLocation;

void BezierTranslationTrack::validate(const std::vector<TranslationKey>& keys) {
  if (keys.empty()) throw KeyError(0, "", "a translation track needs at least one key");
  for (std::size_t j = 0; j < keys.size(); ++j) {
    const TranslationKey& k = keys[j];
    if (!std::isfinite(k.time)) throw KeyError(j, "time", "time is not a finite number");
    if (j > 0 && !(k.time > keys[j - 1].time))
      throw KeyError(j, "time", "keyframe times must strictly increase");
    if (!k.point.allFinite()) throw KeyError(j, "point", "point is not finite");
    if (!k.in.allFinite()) throw KeyError(j, "in", "in handle is not finite");
    if (!k.out.allFinite()) throw KeyError(j, "out", "out handle is not finite");
  }
}

BezierTranslationTrack::BezierTranslationTrack(std::vector<TranslationKey> keys)
    : keys_(std::move(keys)) {
  validate(keys_);
  times_.reserve(keys_.size());
  for (const TranslationKey& k : keys_) times_.push_back(k.time);
}

std::array<Eigen::Vector3d, 4> BezierTranslationTrack::control_points(std::size_t j) const {
  return {keys_[j].point, keys_[j].out, keys_[j + 1].in, keys_[j + 1].point};
}

Eigen::Vector3d BezierTranslationTrack::evaluate(double t) const {
  const KeyLocation loc = detail::locate(times_, t);
  if (loc.region != KeyLocation::Region::kInside) return keys_[loc.segment].point;
  const auto P = control_points(loc.segment);
  const double f = loc.f;
  const double g = 1.0 - f;
  return g * g * g * P[0] + 3.0 * g * g * f * P[1] + 3.0 * g * f * f * P[2] + f * f * f * P[3];
}

Eigen::Vector3d BezierTranslationTrack::derivative(double t) const {
  const KeyLocation loc = detail::locate(times_, t);
  if (loc.region != KeyLocation::Region::kInside) return Eigen::Vector3d::Zero();
  const std::size_t j = loc.segment;
  const auto P = control_points(j);
  const double f = loc.f;
  const double g = 1.0 - f;
  const Eigen::Vector3d dxdf =
      3.0 * g * g * (P[1] - P[0]) + 6.0 * g * f * (P[2] - P[1]) + 3.0 * f * f * (P[3] - P[2]);
  return dxdf / (times_[j + 1] - times_[j]);
}

}  // namespace reconfig::motion
