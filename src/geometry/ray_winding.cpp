#include "reconfig/geometry/ray_winding.h"

#include <cmath>
#include <limits>
#include <optional>

#include "reconfig/geometry/certain_plane.h"

namespace reconfig::geometry {
namespace {

/// Shewchuk's bound on the error of a floating-point 2D orientation determinant, relative to
/// the sum of its two products' magnitudes ("Adaptive Precision Floating-Point Arithmetic and
/// Fast Robust Geometric Predicates", ccwerrboundA; ε = 2^-53).
constexpr double kEpsilon = 1.1102230246251565e-16;
constexpr double kOrientationBound = (3.0 + 16.0 * kEpsilon) * kEpsilon;
/// Below this the products may have underflowed, where the relative bound does not hold.
constexpr double kTinyProduct = 1e-280;

/// The ray from q along +axis (direction +1) or −axis (−1).
struct AxisRay {
  int axis = 0, direction = 1;
};

/// The axis-aligned direction that leaves `box` soonest from q (ties: the first found).
AxisRay shortest_exit(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& q) {
  AxisRay best;
  double nearest = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis)
    for (const int direction : {-1, 1}) {
      const double way = direction > 0 ? box.max()[axis] - q[axis] : q[axis] - box.min()[axis];
      if (way < nearest) {
        nearest = way;
        best = {axis, direction};
      }
    }
  return best;
}

/// What the triangle adds to the ray's winding count: ±1 where the ray crosses it (+1 where its
/// normal points along the ray), 0 where it does not; nothing where that cannot be decided.
std::optional<int> crossing(const TriangleCorners& t, const Eigen::Vector3d& q, const AxisRay& ray) {
  const int i = (ray.axis + 1) % 3, j = (ray.axis + 2) % 3;
  int sign = 0;
  bool unsure = false;
  for (int k = 0; k < 3; ++k) {
    const int o = certain_orientation_2d(t[k], t[(k + 1) % 3], q, i, j);
    if (o == 0) {
      unsure = true;
    } else if (sign == 0) {
      sign = o;
    } else if (o != sign) {
      return 0;  // q's projection lies strictly outside one edge: the ray's line misses it
    }
  }
  if (unsure) return std::nullopt;  // on an edge's or a corner's projection, or too close to tell
  // q's projection lies strictly inside the triangle's, whose orientation in (i, j) is the
  // sign of the normal's component n_axis. The line meets the plane at q + s·direction·e_axis
  // with s = −n·(q − t0) / (direction·n_axis): ahead of q when n·(q − t0) has the sign of
  // −direction·n_axis. The normal points along the ray when direction·n_axis > 0.
  const int side = certain_side(certain_plane(t[0], t[1], t[2]), q);
  if (side == 0) return std::nullopt;  // q on the plane, or too close to tell
  return side == -ray.direction * sign ? ray.direction * sign : 0;
}

}  // namespace

int certain_orientation_2d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, int i, int j) {
  const double left = (a[i] - c[i]) * (b[j] - c[j]);
  const double right = (a[j] - c[j]) * (b[i] - c[i]);
  const double det = left - right;
  const double bound = kOrientationBound * (std::abs(left) + std::abs(right));
  const double magnitude = std::abs(det);
  if (!(magnitude > bound) || !(magnitude > kTinyProduct)) return 0;  // also NaN
  return det > 0 ? 1 : -1;
}

RayWinding axis_ray_winding(const TriangleBvh& tree, const Eigen::Vector3d& q) {
  const Eigen::AlignedBox3d& bounds = tree.bounds();
  if (!bounds.contains(q)) return {true, 0};
  const AxisRay ray = shortest_exit(bounds, q);
  Eigen::AlignedBox3d path(q, q);  // the ray up to (and past) the box's side
  if (ray.direction > 0) {
    path.max()[ray.axis] = std::numeric_limits<double>::infinity();
  } else {
    path.min()[ray.axis] = -std::numeric_limits<double>::infinity();
  }
  RayWinding result{true, 0};
  tree.for_each_overlapping(path, [&](int, const TriangleCorners& t) {
    if (!result.certain) return;
    const std::optional<int> c = crossing(t, q, ray);
    if (c) {
      result.winding += *c;
    } else {
      result.certain = false;
    }
  });
  return result;
}

}  // namespace reconfig::geometry
