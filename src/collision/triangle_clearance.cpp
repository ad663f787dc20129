#include "reconfig/collision/triangle_clearance.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "reconfig/geometry/triangle_closest_points.h"

namespace reconfig::collision {
namespace {

using Eigen::Vector3d;

TriangleCorners corners_at(const TriangleCorners& start, const TriangleCorners& end, double s) {
  return {start[0] + s * (end[0] - start[0]), start[1] + s * (end[1] - start[1]), start[2] + s * (end[2] - start[2])};
}

/// The gap between the triangles along u: how far b's lowest corner lies above a's highest.
double gap_along(const Vector3d& u, const TriangleCorners& a, const TriangleCorners& b) {
  const double top_a = std::max({u.dot(a[0]), u.dot(a[1]), u.dot(a[2])});
  const double bottom_b = std::min({u.dot(b[0]), u.dot(b[1]), u.dot(b[2])});
  return bottom_b - top_a;
}

class ClearanceSearch {
 public:
  explicit ClearanceSearch(const TriangleClearanceRequest& request) : r_(request) {
    double move_a = 0, move_b = 0;
    for (int k = 0; k < 3; ++k) {
      move_a = std::max(move_a, (r_.a_end[k] - r_.a_start[k]).norm());
      move_b = std::max(move_b, (r_.b_end[k] - r_.b_start[k]).norm());
    }
    lipschitz_ = move_a + move_b;
  }

  void search_piece(double lo, double hi) {
    ++result_.pieces;
    if (r_.relevant && !r_.relevant(lo, hi)) return;
    const double mid = (lo + hi) / 2, half = (hi - lo) / 2;
    const TriangleCorners a = corners_at(r_.a_start, r_.a_end, mid), b = corners_at(r_.b_start, r_.b_end, mid);
    const geometry::TriangleClosestPoints near = geometry::triangle_closest_points(a, b);
    const double drift = lipschitz_ * half;
    if (near.distance + drift < r_.clearance - r_.rounding) return add_piece(lo, hi);  // closer throughout
    if (near.distance - drift >= r_.clearance + r_.rounding || apart_throughout(a, b, near, lo, hi)) return;
    if (hi - lo <= r_.time_tolerance) return add_piece(lo, hi);
    search_piece(lo, mid);
    search_piece(mid, hi);
  }

  TriangleClearanceResult result() && { return std::move(result_); }

 private:
  void add_piece(double lo, double hi) { result_.intervals.push_back({lo, hi}); }

  /// Whether some direction — from a's nearest point to b's, or either normal — keeps the
  /// triangles at least C apart at both ends of [lo, hi] (then throughout: the gap is concave).
  bool apart_throughout(const TriangleCorners& a, const TriangleCorners& b,
                        const geometry::TriangleClosestPoints& near, double lo, double hi) const {
    const TriangleCorners a_lo = corners_at(r_.a_start, r_.a_end, lo), a_hi = corners_at(r_.a_start, r_.a_end, hi);
    const TriangleCorners b_lo = corners_at(r_.b_start, r_.b_end, lo), b_hi = corners_at(r_.b_start, r_.b_end, hi);
    const double needed = r_.clearance + r_.rounding;
    const auto separates = [&](Vector3d u) {
      const double length = u.norm();
      if (!(length > 0) || !std::isfinite(length)) return false;
      u /= length;
      if (gap_along(u, a, b) < 0) u = -u;  // b above a along u
      return gap_along(u, a_lo, b_lo) >= needed && gap_along(u, a_hi, b_hi) >= needed;
    };
    return separates(near.on_b - near.on_a) || separates((a[1] - a[0]).cross(a[2] - a[0])) ||
           separates((b[1] - b[0]).cross(b[2] - b[0]));
  }

  const TriangleClearanceRequest& r_;
  double lipschitz_ = 0;
  TriangleClearanceResult result_;
};

}  // namespace

TriangleClearanceResult triangles_closer_than(const TriangleClearanceRequest& request) {
  ClearanceSearch search(request);
  search.search_piece(0, 1);
  return std::move(search).result();
}

}  // namespace reconfig::collision
