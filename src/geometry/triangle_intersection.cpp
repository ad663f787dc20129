#include "reconfig/geometry/triangle_intersection.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Intersections_3/Point_3_Segment_3.h>
#include <CGAL/Intersections_3/Point_3_Triangle_3.h>
#include <CGAL/Intersections_3/Segment_3_Segment_3.h>
#include <CGAL/Intersections_3/Segment_3_Triangle_3.h>
#include <CGAL/Intersections_3/Triangle_3_Triangle_3.h>

#include <cassert>
#include <cmath>

#include "geometry/detail/exact_predicates.h"

namespace reconfig::geometry {
namespace detail {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Segment = K::Segment_3;
using Triangle = K::Triangle_3;

Point point(const Vec3& p) { return {p.x(), p.y(), p.z()}; }

bool finite(const Vec3& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

}  // namespace

bool collinear(const Vec3& p, const Vec3& q, const Vec3& r) { return CGAL::collinear(point(p), point(q), point(r)); }

bool coplanar(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s) {
  return CGAL::coplanar(point(p), point(q), point(r), point(s));
}

int coplanar_orientation(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s) {
  return static_cast<int>(CGAL::coplanar_orientation(point(p), point(q), point(r), point(s)));
}

bool strictly_ordered_along_line(const Vec3& p, const Vec3& q, const Vec3& r) {
  return CGAL::collinear_are_strictly_ordered_along_line(point(p), point(q), point(r));
}

Reduced reduce(const Vec3* p, int n) {
  assert(n >= 1 && n <= 3);
  if (n == 1) return {1, {0, 0, 0}};
  if (n == 2) return p[0] == p[1] ? Reduced{1, {0, 0, 0}} : Reduced{2, {0, 1, 0}};
  if (!collinear(p[0], p[1], p[2])) return {3, {0, 1, 2}};
  if (p[0] == p[1] && p[1] == p[2]) return {1, {0, 0, 0}};
  // Collinear, not all equal: keep the two extreme corners.
  const Point q0 = point(p[0]), q1 = point(p[1]), q2 = point(p[2]);
  if (CGAL::collinear_are_ordered_along_line(q0, q1, q2)) return {2, {0, 2, 0}};
  if (CGAL::collinear_are_ordered_along_line(q1, q0, q2)) return {2, {1, 2, 0}};
  return {2, {0, 1, 0}};
}

namespace {

/// Exact decision on reduced simplices.
bool simplices_intersect(const Vec3* a, const Reduced& ra, const Vec3* b, const Reduced& rb) {
  if (ra.count > rb.count) return simplices_intersect(b, rb, a, ra);
  const auto A = [&](int i) { return point(a[ra.index[i]]); };
  const auto B = [&](int i) { return point(b[rb.index[i]]); };
  switch (ra.count * 3 + rb.count) {
    case 1 * 3 + 1:
      return A(0) == B(0);
    case 1 * 3 + 2:
      return Segment(B(0), B(1)).has_on(A(0));
    case 1 * 3 + 3:
      return Triangle(B(0), B(1), B(2)).has_on(A(0));
    case 2 * 3 + 2:
      return CGAL::do_intersect(Segment(A(0), A(1)), Segment(B(0), B(1)));
    case 2 * 3 + 3:
      return CGAL::do_intersect(Segment(A(0), A(1)), Triangle(B(0), B(1), B(2)));
    case 3 * 3 + 3:
      return CGAL::do_intersect(Triangle(A(0), A(1), A(2)), Triangle(B(0), B(1), B(2)));
    default:
      assert(false);
      return false;
  }
}

/// Closed boxes of the two corner sets overlap (exact on doubles; false if any NaN).
bool boxes_overlap(const Vec3* a, int na, const Vec3* b, int nb) {
  for (int d = 0; d < 3; ++d) {
    double amin = a[0][d], amax = a[0][d], bmin = b[0][d], bmax = b[0][d];
    for (int i = 1; i < na; ++i) {
      amin = std::min(amin, a[i][d]);
      amax = std::max(amax, a[i][d]);
    }
    for (int i = 1; i < nb; ++i) {
      bmin = std::min(bmin, b[i][d]);
      bmax = std::max(bmax, b[i][d]);
    }
    if (!(amin <= bmax && bmin <= amax)) return false;
  }
  return true;
}

bool all_finite(const Vec3* p, int n) {
  for (int i = 0; i < n; ++i)
    if (!finite(p[i])) return false;
  return true;
}

}  // namespace

bool hulls_intersect(const Vec3* a, int na, const Vec3* b, int nb) {
  if (!boxes_overlap(a, na, b, nb)) return false;
  if (!all_finite(a, na) || !all_finite(b, nb)) return false;
  return simplices_intersect(a, reduce(a, na), b, reduce(b, nb));
}

}  // namespace detail

bool triangles_intersect(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1, const Eigen::Vector3d& a2,
                         const Eigen::Vector3d& b0, const Eigen::Vector3d& b1, const Eigen::Vector3d& b2) {
  const detail::Vec3 a[3] = {a0, a1, a2};
  const detail::Vec3 b[3] = {b0, b1, b2};
  return detail::hulls_intersect(a, 3, b, 3);
}

TriangleContact intersect_triangles(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1,
                                    const Eigen::Vector3d& a2, const Eigen::Vector3d& b0,
                                    const Eigen::Vector3d& b1, const Eigen::Vector3d& b2) {
  using namespace detail;
  const Vec3 a[3] = {a0, a1, a2};
  const Vec3 b[3] = {b0, b1, b2};
  TriangleContact contact;
  if (!all_finite(a, 3) || !all_finite(b, 3)) return contact;
  const Reduced ra = reduce(a, 3), rb = reduce(b, 3);
  // All six corners in one plane. A degenerate triangle lies on the hull of its reduced
  // corners, so testing the reduced ones suffices.
  if (ra.count == 3) {
    contact.coplanar = coplanar(a0, a1, a2, b0) && coplanar(a0, a1, a2, b1) && coplanar(a0, a1, a2, b2);
  } else if (rb.count == 3) {
    contact.coplanar = coplanar(b0, b1, b2, a0) && coplanar(b0, b1, b2, a1) && coplanar(b0, b1, b2, a2);
  } else if (ra.count == 2 && rb.count == 2) {
    contact.coplanar = coplanar(a[ra.index[0]], a[ra.index[1]], b[rb.index[0]], b[rb.index[1]]);
  } else {
    contact.coplanar = true;  // a point and a segment (or point) always share a plane
  }
  if (!boxes_overlap(a, 3, b, 3) || !simplices_intersect(a, ra, b, rb)) return contact;
  contact.intersect = true;
  exact_contact(a, ra, b, rb, contact);
  return contact;
}

}  // namespace reconfig::geometry
