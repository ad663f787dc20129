#include "reconfig/collision/spacetime_proxy.h"

#include <algorithm>
#include <cassert>
#include <functional>

#include "reconfig/motion/motion_bounds.h"

namespace reconfig::collision {
namespace {

/// (a, b) ↦ bound on how far the part's vertices stray from straight lines over [a, b]; empty
/// when the part has no track (it holds still).
std::function<double(double, double)> deviation_bound(const scene::Reconfigurable& scene, int transition, int part) {
  const scene::Part& p = scene.parts[part];
  const scene::Transition& tr = scene.transitions[transition];
  const auto it = tr.tracks.find(p.name);
  if (it == tr.tracks.end()) return {};
  const double radius = (p.mesh.V.rowwise() - p.center.transpose()).rowwise().norm().maxCoeff();
  if (const auto* screw = std::get_if<scene::ScrewPosesTrack>(&it->second)) {
    auto track = std::make_shared<motion::ScrewTrack>(screw->poses, p.center);
    return [track, radius](double a, double b) { return motion::screw_motion_bound(*track, radius, a, b).deviation; };
  }
  const auto& keyed = std::get<scene::KeyframedTrack>(it->second);
  const motion::Pose hold = scene.states[scene.find_state(tr.from)].pose_of(p.name);
  const Eigen::Vector3d x = hold.translation;
  auto translation = std::make_shared<motion::BezierTranslationTrack>(
      keyed.translation.empty() ? std::vector<motion::TranslationKey>{{0.0, x, x, x}} : keyed.translation);
  auto rotation = std::make_shared<motion::SlerpRotationTrack>(
      keyed.rotation.empty() ? std::vector<motion::RotationKey>{{0.0, hold.rotation}} : keyed.rotation);
  return [translation, rotation, radius](double a, double b) {
    return motion::keyframed_motion_bound(*translation, *rotation, radius, a, b).deviation;
  };
}

void sample(PartProxy& proxy, const scene::Reconfigurable& scene, int transition, int part,
            const std::vector<double>& times) {
  const Eigen::Vector3d center = scene.parts[part].center;
  for (double t : times) {
    proxy.times.push_back(t);
    proxy.poses.push_back(scene.pose_at(transition, part, t).to_isometry(center));
  }
}

/// Samples [t0, t1] (both ends included) and returns the deviation bound reached.
double sample_range(PartProxy& proxy, const std::function<double(double, double)>& bound,
                    const scene::Reconfigurable& scene, int transition, int part, double tolerance, double t0,
                    double t1, double min_step) {
  if (!bound) {
    sample(proxy, scene, transition, part, {t0, t1});
    return 0;
  }
  const motion::AdaptiveSamples samples = motion::adaptive_time_samples(bound, t0, t1, tolerance, min_step);
  sample(proxy, scene, transition, part, samples.times);
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
  proxy.deviation = sample_range(proxy, deviation_bound(scene, transition, part), scene, transition, part, tolerance,
                                 0.0, 1.0, min_step);
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
