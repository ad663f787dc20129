#include "reconfig/resolve/proximity.h"

#include "reconfig/geometry/triangle_closest_points.h"

namespace reconfig::resolve {

Proximity proximity(const PartShape& a, const Eigen::Isometry3d& place_a, const PartShape& b,
                    const Eigen::Isometry3d& place_b, double reach) {
  const Eigen::Isometry3d b_to_a = place_a.inverse() * place_b;
  Proximity result;
  result.distance = reach;
  geometry::TriangleClosestPoints nearest;
  nearest.distance = reach;
  a.tree().for_each_pair_within(b.tree(), b_to_a, reach, [&](const geometry::TriangleBvh::PlacedPair& placed) {
    if (nearest.distance == 0) return;
    const geometry::TriangleClosestPoints pair = geometry::triangle_closest_points(placed.f_corners, placed.g_corners);
    if (pair.distance < nearest.distance) nearest = pair;
  });
  const double deficit = reach - nearest.distance;
  if (!(deficit > 1e-9 * reach)) return result;
  result.distance = nearest.distance;
  result.deficit = deficit;
  result.nearest_a = place_a * nearest.on_a;
  result.nearest_b = place_a * nearest.on_b;
  if (nearest.distance > 0) {
    const Eigen::Vector3d n = (result.nearest_a - result.nearest_b) / nearest.distance;
    result.gradient.add_point(result.nearest_a, -n);
  }
  return result;
}

double proximity_reach(const collision::DetectorOptions& detector) { return 2 * detector.tolerance; }

}  // namespace reconfig::resolve
