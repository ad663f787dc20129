#pragma once
// Random tracks and poses for the motion tests (fixed seeds, reproducible).

#include "reconfig/motion/bezier_translation_track.h"
#include "reconfig/motion/pose.h"
#include "reconfig/motion/slerp_rotation_track.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <random>
#include <vector>

namespace reconfig::motion::testing {

inline Eigen::Vector3d random_vector(std::mt19937& rng, double scale = 1.0) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

inline Eigen::Quaterniond random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized();
}

inline Eigen::Isometry3d random_isometry(std::mt19937& rng, double scale = 3.0) {
  Eigen::Isometry3d M = Eigen::Isometry3d::Identity();
  M.linear() = random_rotation(rng).toRotationMatrix();
  M.translation() = random_vector(rng, scale);
  return M;
}

/// Strictly increasing random times starting at t0, gaps in [0.1, 1].
inline std::vector<double> random_times(std::mt19937& rng, int n, double t0 = 0.0) {
  std::uniform_real_distribution<double> gap(0.1, 1.0);
  std::vector<double> times{t0};
  for (int i = 1; i < n; ++i) times.push_back(times.back() + gap(rng));
  return times;
}

inline BezierTranslationTrack random_translation_track(std::mt19937& rng, int n) {
  std::vector<TranslationKey> keys;
  for (double s : random_times(rng, n)) {
    TranslationKey k;
    k.time = s;
    k.point = random_vector(rng, 2.0);
    k.in = k.point + random_vector(rng, 0.7);
    k.out = k.point + random_vector(rng, 0.7);
    keys.push_back(k);
  }
  return BezierTranslationTrack(keys);
}

/// Rotation keys that turn by up to `max_step` radians per segment.
inline SlerpRotationTrack random_rotation_track(std::mt19937& rng, int n, double max_step = 2.5) {
  std::vector<RotationKey> keys;
  Eigen::Quaterniond q = random_rotation(rng);
  std::uniform_real_distribution<double> angle(0.0, max_step);
  std::uniform_int_distribution<int> sign(0, 1);
  for (double s : random_times(rng, n)) {
    keys.push_back({s, sign(rng) ? q : Eigen::Quaterniond(-q.coeffs())});
    const Eigen::Vector3d axis = random_vector(rng).normalized();
    q = Eigen::Quaterniond(Eigen::AngleAxisd(angle(rng), axis)) * q;
  }
  return SlerpRotationTrack(keys);
}

/// A time strictly inside (s_0, s_last) and at least `margin` away from every key time.
template <class Track>
double random_time_off_keys(std::mt19937& rng, const Track& track, double margin = 1e-3) {
  std::uniform_real_distribution<double> u(track.start_time(), track.end_time());
  for (;;) {
    const double t = u(rng);
    bool ok = true;
    for (const auto& k : track.keys()) ok = ok && std::abs(t - k.time) > margin;
    if (ok) return t;
  }
}

}  // namespace reconfig::motion::testing
