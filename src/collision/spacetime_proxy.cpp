#include "reconfig/collision/spacetime_proxy.h"

#include <algorithm>
#include <cassert>
#include <functional>

#include "reconfig/motion/motion_bounds.h"

namespace reconfig::collision {
namespace {

/// A part's motion over a transition, its tracks built once: its pose at any time (the same,
/// bit for bit, as `Reconfigurable::pose_at`) and (a, b) ↦ a bound on how far its vertices stray
/// from straight lines over [a, b], empty when the part has no track (it holds still).
struct PartMotion {
  std::function<motion::Pose(double)> pose;
  std::function<double(double, double)> deviation;
};

PartMotion part_motion(const scene::Reconfigurable& scene, int transition, int part) {
  const scene::Part& p = scene.parts[part];
  const scene::Transition& tr = scene.transitions[transition];
  const motion::Pose hold = scene.states[scene.find_state(tr.from)].pose_of(p.name);
  const auto it = tr.tracks.find(p.name);
  if (it == tr.tracks.end()) return {[hold](double) { return hold; }, {}};
  const double radius = (p.mesh.V.rowwise() - p.center.transpose()).rowwise().norm().maxCoeff();
  if (const auto* screw = std::get_if<scene::ScrewPosesTrack>(&it->second)) {
    auto track = std::make_shared<motion::ScrewTrack>(screw->poses, p.center);
    return {[track](double t) { return track->evaluate(t); },
            [track, radius](double a, double b) { return motion::screw_motion_bound(*track, radius, a, b).deviation; }};
  }
  const auto& keyed = std::get<scene::KeyframedTrack>(it->second);
  const Eigen::Vector3d x = hold.translation;
  auto translation = std::make_shared<motion::BezierTranslationTrack>(
      keyed.translation.empty() ? std::vector<motion::TranslationKey>{{0.0, x, x, x}} : keyed.translation);
  auto rotation = std::make_shared<motion::SlerpRotationTrack>(
      keyed.rotation.empty() ? std::vector<motion::RotationKey>{{0.0, hold.rotation}} : keyed.rotation);
  return {[translation, rotation, hold, keyed_translation = !keyed.translation.empty(),
           keyed_rotation = !keyed.rotation.empty()](double t) {
            motion::Pose pose = hold;
            if (keyed_translation) pose.translation = translation->evaluate(t);
            if (keyed_rotation) pose.rotation = rotation->evaluate(t);
            return pose;
          },
          [translation, rotation, radius](double a, double b) {
            return motion::keyframed_motion_bound(*translation, *rotation, radius, a, b).deviation;
          }};
}

void sample(PartProxy& proxy, const PartMotion& motion, const Eigen::Vector3d& center, const std::vector<double>& times) {
  for (double t : times) {
    proxy.times.push_back(t);
    proxy.poses.push_back(motion.pose(t).to_isometry(center));
  }
}

/// Samples [t0, t1] (both ends included) and returns the deviation bound reached.
double sample_range(PartProxy& proxy, const PartMotion& motion, const Eigen::Vector3d& center, double tolerance,
                    double t0, double t1, double min_step) {
  if (!motion.deviation) {
    sample(proxy, motion, center, {t0, t1});
    return 0;
  }
  const motion::AdaptiveSamples samples = motion::adaptive_time_samples(motion.deviation, t0, t1, tolerance, min_step);
  sample(proxy, motion, center, samples.times);
  return samples.deviation;
}

bool same_pose(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) { return a.matrix() == b.matrix(); }

void update_moving(PartProxy& proxy) {
  proxy.moving = false;
  for (std::size_t k = 1; k < proxy.poses.size(); ++k) proxy.moving = proxy.moving || !same_pose(proxy.poses[k], proxy.poses[0]);
}

}  // namespace

int PartProxy::step_of(double t) const {
  const auto it = std::upper_bound(times.begin(), times.end(), t);
  const int k = static_cast<int>(it - times.begin()) - 1;
  return std::clamp(k, 0, static_cast<int>(times.size()) - 2);
}

PartProxy build_part_proxy(const scene::Reconfigurable& scene, int transition, int part, double tolerance,
                           double min_step) {
  assert(tolerance > 0);
  PartProxy proxy;
  proxy.deviation = sample_range(proxy, part_motion(scene, transition, part), scene.parts[part].center, tolerance, 0.0,
                                 1.0, min_step);
  update_moving(proxy);
  return proxy;
}

std::optional<std::pair<double, double>> changed_range(const PartProxy& before, const PartProxy& after) {
  const auto same = [&](std::size_t i, std::size_t j) {
    return before.times[i] == after.times[j] && before.poses[i].matrix() == after.poses[j].matrix();
  };
  const std::size_t n = before.times.size(), m = after.times.size();
  std::size_t prefix = 0;
  while (prefix < n && prefix < m && same(prefix, prefix)) ++prefix;
  if (prefix == n && n == m) return std::nullopt;
  std::size_t suffix = 0;
  while (suffix < n - prefix && suffix < m - prefix && same(n - 1 - suffix, m - 1 - suffix)) ++suffix;
  const double a = prefix > 0 ? after.times[prefix - 1] : 0.0;
  const double b = suffix > 0 ? after.times[m - suffix] : 1.0;
  return std::pair{a, b};
}

}  // namespace reconfig::collision
