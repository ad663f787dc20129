#include "reconfig/resolve/penetration.h"

#include <cmath>
#include <limits>

#include "reconfig/geometry/ray_winding.h"

namespace reconfig::resolve {
namespace {

/// Whether q (in the outer part's frame, inside its box) is settled as outside the closed,
/// consistently oriented outer part by a ray's winding count, with no distance query.
bool outside_by_ray(const PartShape& outer, const Eigen::Vector3d& q, Penetration& result) {
  if (!outer.oriented) return false;
  ++result.ray_tests;
  const geometry::RayWinding ray = geometry::axis_ray_winding(outer.tree(), q);
  return ray.certain && ray.winding == 0;
}

/// The signed distance of q to the outer part, searched first no farther than `reach` (an
/// upper bound on the distance; +inf: unbounded): a bounded search finds the unbounded one's
/// nearest point or nothing, and then the unbounded search runs. The bound only saves work.
geometry::MeshSignedDistance::Query distance_within(const PartShape& outer, const Eigen::Vector3d& q, double reach) {
  geometry::MeshSignedDistance::Query d;
  const double rounding = 1e-9 * (1 + q.cwiseAbs().maxCoeff());
  if (std::isfinite(reach)) d = outer.distance.query(q, reach * (1 + 1e-9) + rounding);
  if (d.triangle < 0) d = outer.distance.query(q);
  return d;
}

/// Adds the samples of `inner` that lie inside `outer` to `result`; `side` is 0 when `inner` is
/// part a (its samples move with a: the gradient's sign is +1), 1 when it is part b (a's
/// motion moves them the other way relative to a's surface).
void add_inside_samples(const PartShape& inner, const Eigen::Isometry3d& place_inner, const PartShape& outer,
                        const Eigen::Isometry3d& place_outer, int side, Penetration& result) {
  const Eigen::Isometry3d inner_to_outer = place_outer.inverse() * place_inner;
  // The inner part's box, moved into the outer's frame, bounded by a box: nothing to do when
  // that misses the outer part's box.
  const Eigen::Vector3d c = inner_to_outer * inner.bounds.center();
  const Eigen::Vector3d h = inner_to_outer.linear().cwiseAbs() * (0.5 * inner.bounds.sizes());
  if (!Eigen::AlignedBox3d(c - h, c + h).intersects(outer.bounds)) return;
  const double sign = side == 0 ? 1.0 : -1.0;
  const Eigen::Matrix3d R_outer = place_outer.linear();
  // The last sample queried: the distance to a surface is 1-Lipschitz, so the next one is no
  // farther from it than that sample's distance plus the way between them (samples next to
  // each other in a mesh's vertex order are often near each other).
  Eigen::Vector3d last_queried = Eigen::Vector3d::Zero();
  double last_distance = std::numeric_limits<double>::infinity();  // none queried yet
  for (std::size_t s = 0; s < inner.sample_points.size(); ++s) {
    const Eigen::Vector3d q = inner_to_outer * inner.sample_points[s];
    if (!outer.bounds.contains(q) || outside_by_ray(outer, q, result)) continue;
    const geometry::MeshSignedDistance::Query d = distance_within(outer, q, last_distance + (q - last_queried).norm());
    ++result.distance_queries;
    last_queried = q;
    last_distance = std::abs(d.distance);
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
  add_inside_samples(a, place_a, b, place_b, 0, result);
  add_inside_samples(b, place_b, a, place_a, 1, result);
  return result;
}

}  // namespace reconfig::resolve
