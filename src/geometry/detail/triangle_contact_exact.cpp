/// @file
/// Exact constructions of the set two (reduced) triangles share, in CGAL's Epeck kernel.
/// Only reached for pairs already known to intersect, so its cost does not matter for the
/// common "no contact" case; kept apart from the predicates so that file compiles fast.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Intersections_3/Segment_3_Segment_3.h>
#include <CGAL/Intersections_3/Segment_3_Triangle_3.h>
#include <CGAL/Intersections_3/Triangle_3_Triangle_3.h>

#include <cassert>
#include <cmath>
#include <limits>
#include <vector>

#include "geometry/detail/exact_predicates.h"

namespace reconfig::geometry::detail {
namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = K::Point_3;
using Segment = K::Segment_3;
using Triangle = K::Triangle_3;

/// The double nearest to x (within an ulp): the interval approximation when it is already
/// that tight, otherwise rounded from the exact value.
double round(const K::FT& x) {
  const auto& approx = x.approx();
  const double lo = approx.inf(), hi = approx.sup();
  if (lo == hi) return lo;
  const double scale = std::max(std::abs(lo), std::abs(hi));
  if (hi - lo <= 2.0 * std::numeric_limits<double>::epsilon() * scale) return 0.5 * (lo + hi);
  return CGAL::to_double(x.exact());
}

Vec3 round(const Point& p) { return {round(p.x()), round(p.y()), round(p.z())}; }

/// Appends the points (exactly deduplicated) that describe one CGAL intersection result.
struct Collector : boost::static_visitor<void> {
  explicit Collector(std::vector<Point>& points) : out(&points) {}
  std::vector<Point>* out;
  void add(const Point& p) const {
    for (const Point& q : *out)
      if (q == p) return;
    out->push_back(p);
  }
  void operator()(const Point& p) const { add(p); }
  void operator()(const Segment& s) const {
    add(s.source());
    add(s.target());
  }
  void operator()(const Triangle& t) const {
    for (int i = 0; i < 3; ++i) add(t.vertex(i));
  }
  void operator()(const std::vector<Point>& polygon) const {
    for (const Point& p : polygon) add(p);
  }
};

template <class Result>
void collect(const Result& result, std::vector<Point>& out) {
  if (!result) return;  // cannot happen for intersecting inputs; leaves `points` empty
  boost::apply_visitor(Collector(out), *result);
}

}  // namespace

void exact_contact(const Vec3* a, const Reduced& ra, const Vec3* b, const Reduced& rb, TriangleContact& contact) {
  if (ra.count > rb.count) return exact_contact(b, rb, a, ra, contact);
  const auto A = [&](int i) {
    const Vec3& p = a[ra.index[i]];
    return Point(p.x(), p.y(), p.z());
  };
  const auto B = [&](int i) {
    const Vec3& p = b[rb.index[i]];
    return Point(p.x(), p.y(), p.z());
  };
  std::vector<Point> points;
  if (ra.count == 1) {
    points.push_back(A(0));  // a point that touches the other simplex is the contact
  } else if (ra.count == 2 && rb.count == 2) {
    collect(CGAL::intersection(Segment(A(0), A(1)), Segment(B(0), B(1))), points);
  } else if (ra.count == 2) {
    collect(CGAL::intersection(Segment(A(0), A(1)), Triangle(B(0), B(1), B(2))), points);
  } else {
    collect(CGAL::intersection(Triangle(A(0), A(1), A(2)), Triangle(B(0), B(1), B(2))), points);
  }
  contact.points.clear();
  contact.points.reserve(points.size());
  for (const Point& p : points) contact.points.push_back(round(p));
}

}  // namespace reconfig::geometry::detail
