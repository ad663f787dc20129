#include "guaranteed_steps.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>

#include "reconfig/motion/motion_bounds.h"

namespace reconfig::bench {
namespace {

/// (a, b) ↦ displacement bound of one part's vertices over [a, b]; empty if it has no track.
std::function<double(double, double)> displacement_of(const scene::Reconfigurable& scene, int transition, int part) {
  const scene::Part& p = scene.parts[part];
  const scene::Transition& tr = scene.transitions[transition];
  const auto it = tr.tracks.find(p.name);
  if (it == tr.tracks.end() || p.mesh.V.rows() == 0) return {};
  const double radius = (p.mesh.V.rowwise() - p.center.transpose()).rowwise().norm().maxCoeff();
  if (const auto* screw = std::get_if<scene::ScrewPosesTrack>(&it->second)) {
    auto track = std::make_shared<motion::ScrewTrack>(screw->poses, p.center);
    return [track, radius](double a, double b) { return motion::screw_motion_bound(*track, radius, a, b).displacement; };
  }
  const auto& keyed = std::get<scene::KeyframedTrack>(it->second);
  const motion::Pose hold = scene.states[scene.find_state(tr.from)].pose_of(p.name);
  const Eigen::Vector3d x = hold.translation;
  auto translation = std::make_shared<motion::BezierTranslationTrack>(
      keyed.translation.empty() ? std::vector<motion::TranslationKey>{{0.0, x, x, x}} : keyed.translation);
  auto rotation = std::make_shared<motion::SlerpRotationTrack>(
      keyed.rotation.empty() ? std::vector<motion::RotationKey>{{0.0, hold.rotation}} : keyed.rotation);
  return [translation, rotation, radius](double a, double b) {
    return motion::keyframed_motion_bound(*translation, *rotation, radius, a, b).displacement;
  };
}

/// The largest displacement bound over the steps of k / n, over every part.
double worst_step(const std::vector<std::function<double(double, double)>>& parts, int n) {
  double worst = 0;
  for (const auto& displacement : parts)
    for (int k = 0; k < n; ++k) worst = std::max(worst, displacement(static_cast<double>(k) / n, static_cast<double>(k + 1) / n));
  return worst;
}

}  // namespace

double vertex_displacement_bound(const scene::Reconfigurable& scene, int transition, int part, double a, double b) {
  const auto displacement = displacement_of(scene, transition, part);
  return displacement ? displacement(a, b) : 0.0;
}

GuaranteedSamples guaranteed_samples(const scene::Reconfigurable& scene, int transition, double tolerance) {
  if (!(tolerance > 0)) throw std::invalid_argument("guaranteed_samples: the tolerance must be > 0");
  std::vector<std::function<double(double, double)>> parts;
  for (int p = 0; p < static_cast<int>(scene.parts.size()); ++p)
    if (auto displacement = displacement_of(scene, transition, p)) parts.push_back(std::move(displacement));
  // The bound is about proportional to the step: scale n by how far the worst step is over,
  // until none is (a few rounds).
  int n = 1;
  double worst = worst_step(parts, n);
  while (worst > tolerance) {
    const double scaled = std::ceil(n * worst / tolerance * 1.01);
    if (scaled > 1e8) throw std::runtime_error("guaranteed_samples: more than 1e8 samples needed");
    n = std::max(n + 1, static_cast<int>(scaled));
    worst = worst_step(parts, n);
  }
  GuaranteedSamples samples;
  for (int k = 0; k <= n; ++k) samples.times.push_back(static_cast<double>(k) / n);
  samples.max_displacement = worst;
  return samples;
}

}  // namespace reconfig::bench
