#include "reconfig/resolve/proximity.h"

#include "reconfig/geometry/triangle_closest_points.h"

namespace reconfig::resolve {
namespace {

geometry::TriangleCorners corners(const geometry::TriangleBvh& tree, int f, const Eigen::Isometry3d& place) {
  const Eigen::MatrixX3d& V = tree.vertices();
  const Eigen::MatrixX3i& F = tree.faces();
  return {place * Eigen::Vector3d(V.row(F(f, 0))), place * Eigen::Vector3d(V.row(F(f, 1))),
          place * Eigen::Vector3d(V.row(F(f, 2)))};
}

}  // namespace

Proximity proximity(const PartShape& a, const Eigen::Isometry3d& place_a, const PartShape& b,
                    const Eigen::Isometry3d& place_b, double reach) {
  const Eigen::Isometry3d b_to_a = place_a.inverse() * place_b;
  Proximity result;
  result.distance = reach;
  geometry::TriangleClosestPoints nearest;
  nearest.distance = reach;
  a.tree().for_each_pair_within(b.tree(), b_to_a, reach, [&](int fa, int fb) {
    if (nearest.distance == 0) return;
    const geometry::TriangleClosestPoints pair = geometry::triangle_closest_points(
        corners(a.tree(), fa, Eigen::Isometry3d::Identity()), corners(b.tree(), fb, b_to_a));
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
