#include "reconfig/resolve/penetration.h"

namespace reconfig::resolve {
namespace {

/// Adds the samples of `inner` that lie inside `outer` to `result`; `sign` is +1 when `inner`
/// is part a (its samples move with a), −1 when it is part b (a's motion moves them the other
/// way relative to a's surface).
void add_inside_samples(const PartShape& inner, const Eigen::Isometry3d& place_inner, const PartShape& outer,
                        const Eigen::Isometry3d& place_outer, double sign, Penetration& result) {
  const Eigen::Isometry3d inner_to_outer = place_outer.inverse() * place_inner;
  // The inner part's box, moved into the outer's frame, bounded by a box: nothing to do when
  // that misses the outer part's box.
  const Eigen::Vector3d c = inner_to_outer * inner.bounds.center();
  const Eigen::Vector3d h = inner_to_outer.linear().cwiseAbs() * (0.5 * inner.bounds.sizes());
  if (!Eigen::AlignedBox3d(c - h, c + h).intersects(outer.bounds)) return;
  const Eigen::Matrix3d R_outer = place_outer.linear();
  for (std::size_t s = 0; s < inner.sample_points.size(); ++s) {
    const Eigen::Vector3d q = inner_to_outer * inner.sample_points[s];
    if (!outer.bounds.contains(q)) continue;
    const geometry::MeshSignedDistance::Query d = outer.distance.query(q);
    if (d.triangle < 0 || d.distance >= 0) continue;
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
                        const Eigen::Isometry3d& place_b) {
  Penetration result;
  add_inside_samples(a, place_a, b, place_b, +1.0, result);
  add_inside_samples(b, place_b, a, place_a, -1.0, result);
  return result;
}

}  // namespace reconfig::resolve
