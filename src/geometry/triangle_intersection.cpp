#include "reconfig/geometry/triangle_intersection.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <Eigen/Geometry>
#include <CGAL/Intersections_3/Point_3_Segment_3.h>
#include <CGAL/Intersections_3/Point_3_Triangle_3.h>
#include <CGAL/Intersections_3/Segment_3_Segment_3.h>
#include <CGAL/Intersections_3/Segment_3_Triangle_3.h>
#include <CGAL/Intersections_3/Triangle_3_Triangle_3.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>

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

/// A point where edge pq crosses a plane (signed distances sp, sq of opposite signs), with
/// a bound on its rounding error.
struct Crossing {
  Vec3 point;
  double error;
};

Crossing crossing(const Vec3& p, const Vec3& q, double sp, double sq, double distance_error) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const double t = sp / (sp - sq);  // |sp - sq| = |sp| + |sq|: no cancellation
  Crossing c;
  c.point = p + t * (q - p);
  c.error = 2.0 * distance_error / (std::abs(sp) + std::abs(sq)) * (q - p).norm() + 8.0 * eps * c.point.norm();
  return c;
}

/// The two crossings of triangle t with the plane of triangle p (normal n, computed from p's
/// edges), for a triangle whose corners' exact sides `side` are all nonzero (one corner alone
/// on its side).
void plane_crossings(const Vec3* t, const int* side, const Vec3* p, const Vec3& n, Crossing* out) {
  const Vec3& o = p[0];
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const int lone = side[0] == side[1] ? 2 : (side[0] == side[2] ? 1 : 0);
  double s[3], size = 0;
  for (int i = 0; i < 3; ++i) {
    s[i] = n.dot(t[i] - o);
    size = std::max(size, (t[i] - o).norm());
  }
  // Rounding of n (a cross product of edges: absolute error ~ eps·|e1|·|e2|, large relative to
  // |n| for slivers), of t − o and of the dot product.
  const double edges = (p[1] - p[0]).norm() * (p[2] - p[0]).norm();
  const double distance_error = 16.0 * eps * (n.norm() + edges) * size;
  int k = 0;
  for (int i = 0; i < 3; ++i)
    if (i != lone) out[k++] = crossing(t[lone], t[i], s[lone], s[i], distance_error);
}

/// The exact sides (−1, 0, +1) of t's corners with respect to the plane through p's corners
/// (all 0 when p is degenerate); those `known` already (nonzero) are taken from it.
std::array<int, 3> sides_of(const Vec3* t, const Vec3* p, const KnownSides& known = {0, 0, 0}) {
  const Point p0 = point(p[0]), p1 = point(p[1]), p2 = point(p[2]);
  std::array<int, 3> side = known;
  for (int i = 0; i < 3; ++i)
    if (side[i] == 0) side[i] = static_cast<int>(CGAL::orientation(p0, p1, p2, point(t[i])));
  return side;
}

bool strictly_one_side(const std::array<int, 3>& side) {
  return side[0] != 0 && side[0] == side[1] && side[1] == side[2];
}

enum class Transversal { kApart, kContact, kUndecided };

/// Fast decision and construction for triangles in general position: every corner strictly
/// off the other's plane (`side_a`: a's corners w.r.t. b's plane; `side_b` the reverse), each
/// triangle crossing the other's plane. The contact is the overlap of the two segments each
/// triangle cuts from the other's plane, computed in doubles with error bounds: kUndecided
/// (the caller then decides and constructs exactly) when the bounds cannot tell which ends
/// bound the overlap, whether it is empty, or whether it is a single point.
Transversal transversal_contact(const Vec3* a, const Vec3* b, const std::array<int, 3>& side_a,
                                const std::array<int, 3>& side_b, TriangleContact& contact) {
  const Vec3 na = (a[1] - a[0]).cross(a[2] - a[0]), nb = (b[1] - b[0]).cross(b[2] - b[0]);
  const Vec3 d = na.cross(nb);
  if (!(d.norm() > 1e-6 * na.norm() * nb.norm())) return Transversal::kUndecided;  // nearly parallel planes
  const Vec3 dir = d.normalized();
  Crossing ca[2], cb[2];
  plane_crossings(a, side_a.data(), b, nb, ca);
  plane_crossings(b, side_b.data(), a, na, cb);
  // Order each pair along the common line; a tie within the error bounds is undecidable.
  const auto param = [&](const Crossing& c) { return dir.dot(c.point); };
  const auto separated = [&](const Crossing& x, const Crossing& y) {
    return std::abs(param(x) - param(y)) > 2.0 * (x.error + y.error);
  };
  if (param(ca[0]) > param(ca[1])) std::swap(ca[0], ca[1]);
  if (param(cb[0]) > param(cb[1])) std::swap(cb[0], cb[1]);
  // One segment wholly before the other, beyond both segments' bounds: apart.
  const double reach_a = 2.0 * std::max(ca[0].error, ca[1].error), reach_b = 2.0 * std::max(cb[0].error, cb[1].error);
  if (param(ca[1]) + reach_a < param(cb[0]) - reach_b || param(cb[1]) + reach_b < param(ca[0]) - reach_a)
    return Transversal::kApart;
  if (!separated(ca[0], cb[0]) || !separated(ca[1], cb[1])) return Transversal::kUndecided;
  const Crossing& start = param(ca[0]) > param(cb[0]) ? ca[0] : cb[0];
  const Crossing& end = param(ca[1]) < param(cb[1]) ? ca[1] : cb[1];
  if (!separated(start, end) || param(start) > param(end)) return Transversal::kUndecided;
  contact.intersect = true;
  contact.points = {start.point, end.point};
  return Transversal::kContact;
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
  return intersect_triangles(a0, a1, a2, b0, b1, b2, {0, 0, 0}, {0, 0, 0});
}

TriangleContact intersect_triangles(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1,
                                    const Eigen::Vector3d& a2, const Eigen::Vector3d& b0,
                                    const Eigen::Vector3d& b1, const Eigen::Vector3d& b2, const KnownSides& known_a,
                                    const KnownSides& known_b) {
  using namespace detail;
  const Vec3 a[3] = {a0, a1, a2};
  const Vec3 b[3] = {b0, b1, b2};
  TriangleContact contact;
  if (!all_finite(a, 3) || !all_finite(b, 3)) return contact;
  // The common cases first, from the six exact sides: one triangle wholly beside the other's
  // plane (then neither is degenerate, and they are not coplanar), or both crossing the other's
  // plane in general position.
  const std::array<int, 3> side_a = sides_of(a, b, known_a), side_b = sides_of(b, a, known_b);
  if (strictly_one_side(side_a) || strictly_one_side(side_b)) return contact;
  const auto nonzero = [](const std::array<int, 3>& side) { return side[0] != 0 && side[1] != 0 && side[2] != 0; };
  if (nonzero(side_a) && nonzero(side_b) && transversal_contact(a, b, side_a, side_b, contact) != Transversal::kUndecided)
    return contact;
  contact = {};
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
