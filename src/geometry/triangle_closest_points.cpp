#include "reconfig/geometry/triangle_closest_points.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "reconfig/geometry/closest_point_on_triangle.h"
#include "reconfig/geometry/triangle_intersection.h"

namespace reconfig::geometry {
namespace {

/// The nearest points of segments [p1, q1] and [p2, q2] (Ericson, Real-Time Collision
/// Detection §5.1.9), degenerate segments included.
std::pair<Eigen::Vector3d, Eigen::Vector3d> segment_closest_points(const Eigen::Vector3d& p1, const Eigen::Vector3d& q1,
                                                                   const Eigen::Vector3d& p2, const Eigen::Vector3d& q2) {
  const Eigen::Vector3d d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  constexpr double kTiny = 1e-300;
  double s = 0, t = 0;
  if (a <= kTiny && e <= kTiny) return {p1, p2};
  if (a <= kTiny) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= kTiny) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;  // parallel: any s
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return {p1 + s * d1, p2 + t * d2};
}

/// The least of the 6 vertex–triangle and 9 edge–edge feature pairs' nearest points, with the
/// squared distance in `distance`.
TriangleClosestPoints nearest_features(const TriangleCorners& a, const TriangleCorners& b) {
  TriangleClosestPoints best;
  best.distance = std::numeric_limits<double>::infinity();
  const auto consider = [&](const Eigen::Vector3d& on_a, const Eigen::Vector3d& on_b) {
    const double d2 = (on_a - on_b).squaredNorm();
    if (d2 < best.distance) best = {d2, on_a, on_b};
  };
  for (const Eigen::Vector3d& p : a) consider(p, closest_point_on_triangle(p, b[0], b[1], b[2]).point);
  for (const Eigen::Vector3d& q : b) consider(closest_point_on_triangle(q, a[0], a[1], a[2]).point, q);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const auto [on_a, on_b] = segment_closest_points(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3]);
      consider(on_a, on_b);
    }
  return best;
}

}  // namespace

TriangleClosestPoints triangle_closest_points(const TriangleCorners& a, const TriangleCorners& b) {
  TriangleClosestPoints best = nearest_features(a, b);
  if (triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2])) {
    best.distance = 0;
    best.on_b = best.on_a;
  } else {
    best.distance = std::sqrt(best.distance);
  }
  return best;
}

double triangle_distance(const TriangleCorners& a, const TriangleCorners& b) {
  if (triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2])) return 0;
  return std::sqrt(nearest_features(a, b).distance);
}

}  // namespace reconfig::geometry
