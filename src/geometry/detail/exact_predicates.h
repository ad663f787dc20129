#pragma once
/// @file
/// Exact geometric predicates on double coordinates (CGAL's filtered Epick predicates behind a
/// CGAL-free interface, implemented in triangle_intersection.cpp). Every answer is exact for
/// the given doubles: no tolerance, never fooled by rounding. Coordinates must be finite.

#include <Eigen/Core>
#include <array>

#include "reconfig/geometry/triangle_intersection.h"

namespace reconfig::geometry::detail {

using Vec3 = Eigen::Vector3d;

/// The simplex a (possibly degenerate) triangle collapses to: `count` = 1 (a point),
/// 2 (a segment between the two extreme corners) or 3 (a proper triangle); `index` lists
/// which of the input corners span it.
struct Reduced {
  int count = 0;
  std::array<int, 3> index{};
};

/// The simplex spanned by corners p[0..n) (n in 1..3).
Reduced reduce(const Vec3* p, int n);

/// Whether the convex hulls of a[0..na) and b[0..nb) (na, nb in 1..3) share a point.
bool hulls_intersect(const Vec3* a, int na, const Vec3* b, int nb);

/// p, q, r on one line (includes repeated points).
bool collinear(const Vec3& p, const Vec3& q, const Vec3& r);

/// p, q, r, s in one plane.
bool coplanar(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s);

/// For coplanar p, q, r, s with p, q, r not collinear: +1 if s and r lie strictly on the same
/// side of the line pq (in their plane), 0 if s is on the line, -1 if strictly opposite.
int coplanar_orientation(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s);

/// For collinear p, q, r: q lies strictly between p and r.
bool strictly_ordered_along_line(const Vec3& p, const Vec3& q, const Vec3& r);

/// Exact construction of what the simplices ra of a and rb of b share (they must intersect);
/// fills `contact.points` (rounded to double). Implemented in triangle_contact_exact.cpp
/// (Epeck, compiled separately).
void exact_contact(const Vec3* a, const Reduced& ra, const Vec3* b, const Reduced& rb,
                   TriangleContact& contact);

}  // namespace reconfig::geometry::detail
