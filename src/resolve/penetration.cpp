#include "reconfig/resolve/penetration.h"

#include <algorithm>
#include <cmath>

namespace reconfig::resolve {
namespace {

using MemoSample = PenetrationMemo::Sample;

/// Bounds on the signed distance at q from what earlier evaluations knew of the same sample:
/// it moved by |q − position| since, and the signed distance by at most as much.
MemoSample bounds_from(std::span<const PenetrationMemo* const> earlier, int side, std::size_t s,
                       const Eigen::Vector3d& q) {
  MemoSample bound;
  bound.position = q;
  bound.lower = -std::numeric_limits<double>::infinity();
  for (const PenetrationMemo* memo : earlier) {
    if (memo == nullptr || memo->samples[side].size() <= s) continue;
    const MemoSample& known = memo->samples[side][s];
    if (std::isnan(known.position.x())) continue;
    const double moved = (q - known.position).norm();
    bound.lower = std::max(bound.lower, known.lower - moved);
    bound.upper_abs = std::min(bound.upper_abs, known.upper_abs + moved);
  }
  return bound;
}

/// Adds the samples of `inner` that lie inside `outer` to `result`; `side` is 0 when `inner` is
/// part a (its samples move with a: the gradient's sign is +1), 1 when it is part b (a's
/// motion moves them the other way relative to a's surface).
void add_inside_samples(const PartShape& inner, const Eigen::Isometry3d& place_inner, const PartShape& outer,
                        const Eigen::Isometry3d& place_outer, int side, std::span<const PenetrationMemo* const> earlier,
                        PenetrationMemo* record, Penetration& result) {
  if (record != nullptr) record->samples[side].assign(inner.sample_points.size(), MemoSample{});
  const Eigen::Isometry3d inner_to_outer = place_outer.inverse() * place_inner;
  // The inner part's box, moved into the outer's frame, bounded by a box: nothing to do when
  // that misses the outer part's box.
  const Eigen::Vector3d c = inner_to_outer * inner.bounds.center();
  const Eigen::Vector3d h = inner_to_outer.linear().cwiseAbs() * (0.5 * inner.bounds.sizes());
  if (!Eigen::AlignedBox3d(c - h, c + h).intersects(outer.bounds)) return;
  if (!outer.closed) earlier = {};
  const double sign = side == 0 ? 1.0 : -1.0;
  const Eigen::Matrix3d R_outer = place_outer.linear();
  for (std::size_t s = 0; s < inner.sample_points.size(); ++s) {
    const Eigen::Vector3d q = inner_to_outer * inner.sample_points[s];
    MemoSample known = bounds_from(earlier, side, s, q);
    // Outside the box, or known to be outside by more than rounding: no query.
    const double box_distance = std::sqrt(outer.bounds.squaredExteriorDistance(q));
    known.lower = std::max(known.lower, box_distance);
    const double rounding = 1e-9 * (1 + q.cwiseAbs().maxCoeff());
    const bool outside = !outer.bounds.contains(q) || known.lower > rounding;
    geometry::MeshSignedDistance::Query d;
    if (!outside) {
      // A search bounded by what the sample can be from the surface finds the same nearest
      // point as an unbounded one; the margin covers the rounding of the bound.
      if (std::isfinite(known.upper_abs)) d = outer.distance.query(q, known.upper_abs * (1 + 1e-9) + rounding);
      if (d.triangle < 0) d = outer.distance.query(q);
      ++result.distance_queries;
      known.lower = d.distance;
      known.upper_abs = std::abs(d.distance);
    }
    if (record != nullptr && outer.closed) record->samples[side][s] = known;
    if (outside || d.triangle < 0 || d.distance >= 0) continue;
    const double w = inner.sample_weights[s];
    result.depth += w * -d.distance;
    ++result.samples_inside;
    // ∂depth/∂q = −(nearest − q)/|nearest − q| (moving toward the surface makes it shallower).
    const Eigen::Vector3d to_surface = R_outer * (d.nearest - q) / -d.distance;
    result.gradient.add_point(place_outer * q, sign * -w * to_surface);
  }
}

}  // namespace

Penetration penetration(const PartShape& a, const Eigen::Isometry3d& place_a, const PartShape& b,
                        const Eigen::Isometry3d& place_b, std::span<const PenetrationMemo* const> earlier,
                        PenetrationMemo* record) {
  Penetration result;
  add_inside_samples(a, place_a, b, place_b, 0, earlier, record, result);
  add_inside_samples(b, place_b, a, place_a, 1, earlier, record, result);
  return result;
}

}  // namespace reconfig::resolve
