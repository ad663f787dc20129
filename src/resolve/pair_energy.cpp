#include "reconfig/resolve/pair_energy.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "reconfig/resolve/intersection_contour.h"
#include "reconfig/resolve/penetration.h"
#include "reconfig/resolve/proximity.h"

namespace reconfig::resolve {
namespace {

/// How close the doubling before the last must have come (a multiple of the accuracy).
constexpr double kEarlierAccuracy = 4;

Eigen::Isometry3d placement(const scene::Reconfigurable& scene, int transition, int part, double t) {
  return scene.pose_at(transition, part, t).to_isometry(scene.parts[part].center);
}

struct PairContext {
  const scene::Reconfigurable& scene;
  const PartShape& a;
  const PartShape& b;
  const PairEnergyRequest& request;
};

EnergySample sample_at(const PairContext& ctx, double t) {
  const PairEnergyRequest& r = ctx.request;
  const Eigen::Isometry3d place_a = placement(ctx.scene, r.transition, r.part_a, t);
  const Eigen::Isometry3d place_b = placement(ctx.scene, r.transition, r.part_b, t);
  const IntersectionContour contour = intersection_contour(ctx.a, place_a, ctx.b, place_b, ContourPolylines::kNone);
  const Penetration depth = penetration(ctx.a, place_a, ctx.b, place_b);
  EnergySample sample;
  sample.time = t;
  sample.contour_length = contour.length;
  sample.penetration = depth.depth;
  sample.gradient = contour_length_gradient(contour);
  sample.gradient += depth.gradient;
  if (r.proximity_reach > 0) {
    if (contour.length > 0 || depth.samples_inside > 0) {
      sample.proximity = r.proximity_reach;  // they overlap: d = 0
    } else {
      const Proximity near = proximity(ctx.a, place_a, ctx.b, place_b, r.proximity_reach);
      sample.proximity = near.deficit;
      sample.gradient += near.gradient;
    }
  }
  return sample;
}

/// n + 1 uniform samples over [t0, t1], in parallel (each is independent; the shapes are built).
std::vector<EnergySample> uniform_samples(const PairContext& ctx, double t0, double t1, int n) {
  std::vector<EnergySample> samples(n + 1);
  tbb::parallel_for(0, n + 1, [&](int i) { samples[i] = sample_at(ctx, t0 + (t1 - t0) * i / n); });
  return samples;
}

/// Adds the midpoint of every pair of consecutive samples, in parallel.
void add_midpoints(const PairContext& ctx, double t0, double t1, std::vector<EnergySample>& samples) {
  const int n = static_cast<int>(samples.size()) - 1;
  std::vector<EnergySample> added(n);
  tbb::parallel_for(0, n, [&](int i) { added[i] = sample_at(ctx, t0 + (t1 - t0) * (2 * i + 1) / (2.0 * n)); });
  std::vector<EnergySample> merged;
  merged.reserve(2 * n + 1);
  for (int i = 0; i <= n; ++i) {
    merged.push_back(samples[i]);
    if (i < n) merged.push_back(added[i]);
  }
  samples = std::move(merged);
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
  if (depth >= 0) return depth;
  const double nearest = by([](const EnergySample& s) { return s.proximity; });
  return nearest >= 0 ? nearest : 0.5 * (t0 + t1);
}

}  // namespace

PairEnergy pair_energy(const scene::Reconfigurable& scene, ShapeCache& shapes, const PairEnergyRequest& request) {
  const PairContext ctx{scene, shapes.shape(scene, request.part_a), shapes.shape(scene, request.part_b), request};
  const double t0 = request.t0, t1 = std::max(request.t0, request.t1);
  const int min_intervals = std::max(1, request.min_intervals);
  int n = min_intervals;
  std::vector<EnergySample> samples = uniform_samples(ctx, t0, t1, n);
  set_trapezoid_weights(samples, t0, t1);
  double energy = integral(samples);
  // Double the samples until the integral settles: a doubling changes it by less than the
  // accuracy right after one that changed it by less than four times that (a first agreement
  // may be luck while a short collision falls between the samples: the doubling before it
  // must have been close too); an all-zero integral is refined once past the minimum.
  double previous_change = std::numeric_limits<double>::infinity();
  while (n < request.max_intervals && t1 > t0) {
    add_midpoints(ctx, t0, t1, samples);
    n *= 2;
    set_trapezoid_weights(samples, t0, t1);
    const double refined = integral(samples);
    const double change = refined > 0 ? std::abs(refined - energy) / refined : std::numeric_limits<double>::infinity();
    energy = refined;
    if (refined == 0 && n >= 2 * min_intervals) break;
    if (change <= request.relative_accuracy && previous_change <= kEarlierAccuracy * request.relative_accuracy) break;
    previous_change = change;
  }
  PairEnergy result;
  result.energy = energy;
  for (const EnergySample& s : samples) {
    result.contour_energy += s.weight * s.contour_length;
    result.penetration_energy += s.weight * s.penetration;
    result.proximity_energy += s.weight * s.proximity;
  }
  result.severity_time = severity_time(samples, t0, t1);
  result.samples = std::move(samples);
  return result;
}

}  // namespace reconfig::resolve
