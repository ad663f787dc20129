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

/// The candidate directions of the separating axis theorem for two triangles (unit length;
/// degenerate ones left out).
std::vector<Vector3d> separating_axes(const TriangleCorners& a, const TriangleCorners& b) {
  std::vector<Vector3d> axes;
  const auto add = [&](const Vector3d& u, double scale) {
    const double length = u.norm();
    if (length > 1e-12 * scale && std::isfinite(length)) axes.push_back(u / length);
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

/// The lowest value over [lo, hi] of u·n(s), n(s) the (unnormalized) normal of the triangle
/// moving from p0 to p1: a quadratic in s.
double lowest_facing(const Vector3d& u, const TriangleCorners& p0, const TriangleCorners& p1, double lo, double hi) {
  const Vector3d e1 = p0[1] - p0[0], e2 = p0[2] - p0[0];
  const Vector3d d1 = (p1[1] - p1[0]) - e1, d2 = (p1[2] - p1[0]) - e2;
  const double c0 = u.dot(e1.cross(e2)), c1 = u.dot(e1.cross(d2) + d1.cross(e2)), c2 = u.dot(d1.cross(d2));
  const auto q = [&](double s) { return c0 + s * (c1 + s * c2); };
  double lowest = std::min(q(lo), q(hi));
  if (c2 > 0) {
    const double vertex = -c1 / (2 * c2);
    if (vertex > lo && vertex < hi) lowest = std::min(lowest, q(vertex));
  }
  return lowest;
}

/// The largest |n(s)| at lo, hi and their middle: the scale of the facing slack.
double normal_scale(const TriangleCorners& p0, const TriangleCorners& p1, double lo, double hi) {
  return std::max({normal_of(at(p0, p1, lo)).norm(), normal_of(at(p0, p1, hi)).norm(),
                   normal_of(at(p0, p1, 0.5 * (lo + hi))).norm()});
}

/// How far X reaches above the lowest point of Y along u (X below Y when ≤ δ).
double overlap(const Vector3d& u, const TriangleCorners& x, const TriangleCorners& y) {
  const double x_top = std::max({u.dot(x[0]), u.dot(x[1]), u.dot(x[2])});
  const double y_bottom = std::min({u.dot(y[0]), u.dot(y[1]), u.dot(y[2])});
  return x_top - y_bottom;
}

struct Moving {
  const TriangleCorners& p0;
  const TriangleCorners& p1;
};

/// Whether the triangle keeps an extent along u of more than `band` over [lo, hi]: two of its
/// vertices (those furthest apart along u at the middle) stay further apart than that at both
/// ends (their difference is linear in time).
bool thick_throughout(const Vector3d& u, const Moving& z, double lo, double hi, double band) {
  const TriangleCorners mid = at(z.p0, z.p1, 0.5 * (lo + hi));
  int top = 0, bottom = 0;
  for (int k = 1; k < 3; ++k) {
    if (u.dot(mid[k]) > u.dot(mid[top])) top = k;
    if (u.dot(mid[k]) < u.dot(mid[bottom])) bottom = k;
  }
  for (const double s : {lo, hi}) {
    const TriangleCorners t = at(z.p0, z.p1, s);
    if (u.dot(t[top]) - u.dot(t[bottom]) <= band) return false;
  }
  return true;
}

/// Whether X stays below Y along u, overlapping by at most δ, over [lo, hi], and each of them
/// that may lie flat in the separating band faces the right way throughout: X's normal never
/// points down, Y's never up.
bool below_throughout(const Vector3d& u, const Moving& x, const Moving& y, double lo, double hi, double delta) {
  if (overlap(u, at(x.p0, x.p1, lo), at(y.p0, y.p1, lo)) > delta) return false;
  if (overlap(u, at(x.p0, x.p1, hi), at(y.p0, y.p1, hi)) > delta) return false;
  const double band = 2 * delta;
  if (!thick_throughout(u, x, lo, hi, band) &&
      lowest_facing(u, x.p0, x.p1, lo, hi) < -kFacingSlack * normal_scale(x.p0, x.p1, lo, hi))
    return false;
  return thick_throughout(u, y, lo, hi, band) ||
         -lowest_facing(-u, y.p0, y.p1, lo, hi) <= kFacingSlack * normal_scale(y.p0, y.p1, lo, hi);
}

void classify(const TriangleCorners& a0, const TriangleCorners& a1, const TriangleCorners& b0,
              const TriangleCorners& b1, double lo, double hi, double delta, int depth, std::vector<TimeInterval>& out) {
  if (touching_throughout(a0, a1, b0, b1, lo, hi, delta)) return;
  const double mid = 0.5 * (lo + hi);
  if (depth == 0 || !(lo < mid && mid < hi)) {
    out.push_back({lo, hi});
    return;
  }
  classify(a0, a1, b0, b1, lo, mid, delta, depth - 1, out);
  classify(a0, a1, b0, b1, mid, hi, delta, depth - 1, out);
}

}  // namespace

bool touching_throughout(const TriangleCorners& a0, const TriangleCorners& a1, const TriangleCorners& b0,
                         const TriangleCorners& b1, double lo, double hi, double delta) {
  const double mid = 0.5 * (lo + hi);
  const Moving a{a0, a1}, b{b0, b1};
  for (const Vector3d& u : separating_axes(at(a0, a1, mid), at(b0, b1, mid)))
    if (below_throughout(u, a, b, lo, hi, delta) || below_throughout(u, b, a, lo, hi, delta)) return true;
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
