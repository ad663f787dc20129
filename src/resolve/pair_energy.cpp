#include "reconfig/resolve/pair_energy.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "reconfig/resolve/intersection_contour.h"
#include "reconfig/resolve/penetration.h"

namespace reconfig::resolve {
namespace {

Eigen::Isometry3d placement(const scene::Reconfigurable& scene, int transition, int part, double t) {
  return scene.pose_at(transition, part, t).to_isometry(scene.parts[part].center);
}

EnergySample sample_at(const scene::Reconfigurable& scene, const PartShape& a, const PartShape& b, int transition,
                       int part_a, int part_b, double t) {
  const Eigen::Isometry3d place_a = placement(scene, transition, part_a, t);
  const Eigen::Isometry3d place_b = placement(scene, transition, part_b, t);
  const IntersectionContour contour = intersection_contour(a, place_a, b, place_b, ContourPolylines::kNone);
  const Penetration depth = penetration(a, place_a, b, place_b);
  EnergySample sample;
  sample.time = t;
  sample.contour_length = contour.length;
  sample.penetration = depth.depth;
  sample.gradient = contour_length_gradient(contour);
  sample.gradient += depth.gradient;
  return sample;
}

/// Evaluates the samples at `times` in parallel (each is independent; the shapes are built).
std::vector<EnergySample> evaluate(const scene::Reconfigurable& scene, const PartShape& a, const PartShape& b,
                                   const PairEnergyRequest& request, const std::vector<double>& times) {
  std::vector<EnergySample> samples(times.size());
  tbb::parallel_for(std::size_t{0}, times.size(), [&](std::size_t i) {
    samples[i] = sample_at(scene, a, b, request.transition, request.part_a, request.part_b, times[i]);
  });
  return samples;
}

/// Trapezoid weights of uniformly spaced samples over [t0, t1].
void set_trapezoid_weights(std::vector<EnergySample>& samples, double t0, double t1) {
  const std::size_t n = samples.size() - 1;
  const double h = n > 0 ? (t1 - t0) / static_cast<double>(n) : 0.0;
  for (std::size_t i = 0; i <= n; ++i) samples[i].weight = (i == 0 || i == n) ? h / 2 : h;
}

double integral(const std::vector<EnergySample>& samples) {
  double sum = 0;
  for (const EnergySample& s : samples) sum += s.weight * s.density();
  return sum;
}

double severity_time(const std::vector<EnergySample>& samples, double t0, double t1) {
  const auto by = [&](auto value) {
    const auto best = std::max_element(samples.begin(), samples.end(),
                                       [&](const EnergySample& x, const EnergySample& y) { return value(x) < value(y); });
    return best != samples.end() && value(*best) > 0 ? best->time : -1.0;
  };
  const double contour = by([](const EnergySample& s) { return s.contour_length; });
  if (contour >= 0) return contour;
  const double depth = by([](const EnergySample& s) { return s.penetration; });
  return depth >= 0 ? depth : 0.5 * (t0 + t1);
}

}  // namespace

PairEnergy pair_energy(const scene::Reconfigurable& scene, ShapeCache& shapes, const PairEnergyRequest& request) {
  const PartShape& a = shapes.shape(scene, request.part_a);
  const PartShape& b = shapes.shape(scene, request.part_b);
  const double t0 = request.t0, t1 = std::max(request.t0, request.t1);
  int n = std::max(1, request.min_intervals);
  std::vector<double> times(n + 1);
  for (int i = 0; i <= n; ++i) times[i] = t0 + (t1 - t0) * i / n;
  std::vector<EnergySample> samples = evaluate(scene, a, b, request, times);
  set_trapezoid_weights(samples, t0, t1);
  double energy = integral(samples);
  // Double the samples until the integral settles: two doublings in a row each change it by
  // less than the accuracy (one may agree by luck while a short collision falls between the
  // samples); an all-zero integral is refined once past the minimum.
  int settled_doublings = 0;
  while (n < request.max_intervals && t1 > t0) {
    std::vector<double> midpoints(n);
    for (int i = 0; i < n; ++i) midpoints[i] = t0 + (t1 - t0) * (2 * i + 1) / (2.0 * n);
    const std::vector<EnergySample> added = evaluate(scene, a, b, request, midpoints);
    std::vector<EnergySample> merged;
    merged.reserve(samples.size() + added.size());
    for (int i = 0; i < n; ++i) {
      merged.push_back(samples[i]);
      merged.push_back(added[i]);
    }
    merged.push_back(samples.back());
    samples = std::move(merged);
    n *= 2;
    set_trapezoid_weights(samples, t0, t1);
    const double refined = integral(samples);
    const bool settled = refined > 0 ? std::abs(refined - energy) <= request.relative_accuracy * refined
                                     : n >= 2 * std::max(1, request.min_intervals);
    energy = refined;
    settled_doublings = settled ? settled_doublings + 1 : 0;
    if (settled_doublings == 2 || (settled && refined == 0)) break;
  }
  PairEnergy result;
  result.energy = energy;
  for (const EnergySample& s : samples) {
    result.contour_energy += s.weight * s.contour_length;
    result.penetration_energy += s.weight * s.penetration;
  }
  result.severity_time = severity_time(samples, t0, t1);
  result.samples = std::move(samples);
  return result;
}

}  // namespace reconfig::resolve
