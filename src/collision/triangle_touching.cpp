#include "reconfig/collision/triangle_touching.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace reconfig::collision {
namespace {

using Eigen::Vector3d;

/// Rounding allowance of the facing conditions (cosines).
constexpr double kFacingSlack = 1e-9;

/// A triangle's vertices at step parameter s (as the narrow phase computes them).
TriangleCorners at(const TriangleCorners& p0, const TriangleCorners& p1, double s) {
  if (s == 0) return p0;
  if (s == 1) return p1;
  return {p0[0] + s * (p1[0] - p0[0]), p0[1] + s * (p1[1] - p0[1]), p0[2] + s * (p1[2] - p0[2])};
}

Vector3d normal_of(const TriangleCorners& t) { return (t[1] - t[0]).cross(t[2] - t[0]); }

/// Up to 17 unit directions.
struct Axes {
  std::array<Vector3d, 17> axis;
  int count = 0;
};

/// The candidate directions of the separating axis theorem for two triangles (unit length;
/// degenerate ones left out), the normals first.
Axes separating_axes(const TriangleCorners& a, const TriangleCorners& b) {
  Axes axes;
  const auto add = [&](const Vector3d& u, double scale) {
    const double length = u.norm();
    if (length > 1e-12 * scale && std::isfinite(length)) axes.axis[axes.count++] = u / length;
  };
  const Vector3d na = normal_of(a), nb = normal_of(b);
  add(na, (a[1] - a[0]).norm() * (a[2] - a[0]).norm());
  add(nb, (b[1] - b[0]).norm() * (b[2] - b[0]).norm());
  for (int i = 0; i < 3; ++i) {
    const Vector3d ea = a[(i + 1) % 3] - a[i];
    for (int j = 0; j < 3; ++j) {
      const Vector3d eb = b[(j + 1) % 3] - b[j];
      add(ea.cross(eb), ea.norm() * eb.norm());
    }
  }
  for (const auto& [t, n] : {std::pair{&a, na}, std::pair{&b, nb}})
    for (int i = 0; i < 3; ++i) {
      const Vector3d e = (*t)[(i + 1) % 3] - (*t)[i];
      add(n.cross(e), n.norm() * e.norm());
    }
  return axes;
}

/// One triangle over [lo, hi]: its corners at both ends and the middle, and its (unnormalized)
/// normal as the exact quadratic n(s) = n0 + s n1 + s² n2.
struct Moving {
  TriangleCorners lo, hi, mid;
  Vector3d n0, n1, n2;
  double normal_scale = 0;  ///< the largest |n| at lo, hi and the middle: the facing slack's scale

  Moving(const TriangleCorners& p0, const TriangleCorners& p1, double s_lo, double s_hi)
      : lo(at(p0, p1, s_lo)), hi(at(p0, p1, s_hi)), mid(at(p0, p1, 0.5 * (s_lo + s_hi))) {
    const Vector3d e1 = p0[1] - p0[0], e2 = p0[2] - p0[0];
    const Vector3d d1 = (p1[1] - p1[0]) - e1, d2 = (p1[2] - p1[0]) - e2;
    n0 = e1.cross(e2);
    n1 = e1.cross(d2) + d1.cross(e2);
    n2 = d1.cross(d2);
    normal_scale = std::max({normal_of(lo).norm(), normal_of(hi).norm(), normal_of(mid).norm()});
  }

  /// The largest value of u·n(s) over [s_lo, s_hi].
  double highest_facing(const Vector3d& u, double s_lo, double s_hi) const {
    const double c0 = u.dot(n0), c1 = u.dot(n1), c2 = u.dot(n2);
    const auto q = [&](double s) { return c0 + s * (c1 + s * c2); };
    double highest = std::max(q(s_lo), q(s_hi));
    if (c2 < 0) {
      const double vertex = -c1 / (2 * c2);
      if (vertex > s_lo && vertex < s_hi) highest = std::max(highest, q(vertex));
    }
    return highest;
  }
};

/// How far X reaches above the lowest point of Y along u (X below Y when ≤ δ).
double overlap(const Vector3d& u, const TriangleCorners& x, const TriangleCorners& y) {
  const double x_top = std::max({u.dot(x[0]), u.dot(x[1]), u.dot(x[2])});
  const double y_bottom = std::min({u.dot(y[0]), u.dot(y[1]), u.dot(y[2])});
  return x_top - y_bottom;
}

/// Whether the triangle keeps an extent along u of more than `band` over the span: two of its
/// vertices (those furthest apart along u at the middle) stay further apart than that at both
/// ends (their difference is linear in time).
bool thick_throughout(const Vector3d& u, const Moving& z, double band) {
  int top = 0, bottom = 0;
  for (int k = 1; k < 3; ++k) {
    if (u.dot(z.mid[k]) > u.dot(z.mid[top])) top = k;
    if (u.dot(z.mid[k]) < u.dot(z.mid[bottom])) bottom = k;
  }
  return u.dot(z.lo[top] - z.lo[bottom]) > band && u.dot(z.hi[top] - z.hi[bottom]) > band;
}

/// Whether X stays below Y along u, overlapping by at most δ, over [s_lo, s_hi], and each of
/// them that may lie flat in the separating band faces the right way throughout: X's normal
/// never points down, Y's never up.
bool below_throughout(const Vector3d& u, const Moving& x, const Moving& y, double s_lo, double s_hi, double delta) {
  if (overlap(u, x.lo, y.lo) > delta || overlap(u, x.hi, y.hi) > delta) return false;
  const double band = 2 * delta;
  if (!thick_throughout(u, x, band) && x.highest_facing(-u, s_lo, s_hi) > kFacingSlack * x.normal_scale) return false;
  return thick_throughout(u, y, band) || y.highest_facing(u, s_lo, s_hi) <= kFacingSlack * y.normal_scale;
}

void classify(const TriangleCorners& a0, const TriangleCorners& a1, const TriangleCorners& b0,
              const TriangleCorners& b1, double lo, double hi, double delta, int depth, std::vector<TimeInterval>& out) {
  // Interfering at both ends: kept whole (only its ends matter to the intervals, and those are
  // refined by re-detection), without trying to certify it.
  const bool ends_interfere = !touching_throughout(a0, a1, b0, b1, lo, lo, delta) &&
                              !touching_throughout(a0, a1, b0, b1, hi, hi, delta);
  if (!ends_interfere && touching_throughout(a0, a1, b0, b1, lo, hi, delta)) return;
  const double mid = 0.5 * (lo + hi);
  if (depth == 0 || ends_interfere || !(lo < mid && mid < hi)) {
    out.push_back({lo, hi});
    return;
  }
  classify(a0, a1, b0, b1, lo, mid, delta, depth - 1, out);
  classify(a0, a1, b0, b1, mid, hi, delta, depth - 1, out);
}

}  // namespace

bool touching_throughout(const TriangleCorners& a0, const TriangleCorners& a1, const TriangleCorners& b0,
                         const TriangleCorners& b1, double lo, double hi, double delta) {
  const Moving a(a0, a1, lo, hi), b(b0, b1, lo, hi);
  const Axes axes = separating_axes(a.mid, b.mid);
  for (int i = 0; i < axes.count; ++i)
    if (below_throughout(axes.axis[i], a, b, lo, hi, delta) || below_throughout(axes.axis[i], b, a, lo, hi, delta))
      return true;
  return false;
}

bool triangles_touch(const TriangleCorners& a, const TriangleCorners& b, double delta) {
  return touching_throughout(a, a, b, b, 0, 0, delta);
}

std::vector<TimeInterval> interference_pieces(const TriangleCorners& a0, const TriangleCorners& a1,
                                              const TriangleCorners& b0, const TriangleCorners& b1,
                                              const std::vector<TimeInterval>& pieces, double delta, int depth) {
  std::vector<TimeInterval> out;
  for (const TimeInterval& piece : pieces) classify(a0, a1, b0, b1, piece.lo, piece.hi, delta, depth, out);
  return out;
}

}  // namespace reconfig::collision
