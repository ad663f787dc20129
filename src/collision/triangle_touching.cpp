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
/// degenerate ones left out), the normals first. Each edge's length and each normal's is
/// computed once.
Axes separating_axes(const TriangleCorners& a, const TriangleCorners& b) {
  Axes axes;
  const auto add = [&](const Vector3d& u, double scale) {
    const double length = u.norm();
    if (length > 1e-12 * scale && std::isfinite(length)) axes.axis[axes.count++] = u / length;
  };
  std::array<Vector3d, 3> ea, eb;  // edge i runs from vertex i to vertex i + 1
  std::array<double, 3> la{}, lb{};
  for (int i = 0; i < 3; ++i) {
    ea[i] = a[(i + 1) % 3] - a[i];
    eb[i] = b[(i + 1) % 3] - b[i];
    la[i] = ea[i].norm();
    lb[i] = eb[i].norm();
  }
  const Vector3d na = normal_of(a), nb = normal_of(b);
  add(na, la[0] * la[2]);  // |a2 − a0| = |a0 − a2|
  add(nb, lb[0] * lb[2]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) add(ea[i].cross(eb[j]), la[i] * lb[j]);
  const double norm_a = na.norm(), norm_b = nb.norm();
  for (int i = 0; i < 3; ++i) add(na.cross(ea[i]), norm_a * la[i]);
  for (int i = 0; i < 3; ++i) add(nb.cross(eb[i]), norm_b * lb[i]);
  return axes;
}

/// One triangle over [lo, hi]: its corners at both ends and the middle, and (computed when
/// first asked for) its unnormalized normal as the exact quadratic n(s) = n0 + s n1 + s² n2.
class Moving {
 public:
  TriangleCorners lo, hi, mid;

  Moving(const TriangleCorners& p0, const TriangleCorners& p1, double s_lo, double s_hi)
      : lo(at(p0, p1, s_lo)), hi(s_hi == s_lo ? lo : at(p0, p1, s_hi)),
        mid(s_hi == s_lo ? lo : at(p0, p1, 0.5 * (s_lo + s_hi))), p0_(p0), p1_(p1) {}

  /// The largest value of u·n(s) over [s_lo, s_hi].
  double highest_facing(const Vector3d& u, double s_lo, double s_hi) const {
    if (!has_normal_) compute_normal();
    const double c0 = u.dot(n0_), c1 = u.dot(n1_), c2 = u.dot(n2_);
    const auto q = [&](double s) { return c0 + s * (c1 + s * c2); };
    double highest = std::max(q(s_lo), q(s_hi));
    if (c2 < 0) {
      const double vertex = -c1 / (2 * c2);
      if (vertex > s_lo && vertex < s_hi) highest = std::max(highest, q(vertex));
    }
    return highest;
  }

  /// The rounding allowance of `highest_facing`: η times the largest |n| at lo, hi and the middle.
  double facing_slack() const {
    if (!has_normal_) compute_normal();
    return kFacingSlack * normal_scale_;
  }

 private:
  void compute_normal() const {
    const Vector3d e1 = p0_[1] - p0_[0], e2 = p0_[2] - p0_[0];
    const Vector3d d1 = (p1_[1] - p1_[0]) - e1, d2 = (p1_[2] - p1_[0]) - e2;
    n0_ = e1.cross(e2);
    n1_ = e1.cross(d2) + d1.cross(e2);
    n2_ = d1.cross(d2);
    normal_scale_ = std::max({normal_of(lo).norm(), normal_of(hi).norm(), normal_of(mid).norm()});
    has_normal_ = true;
  }

  const TriangleCorners& p0_;
  const TriangleCorners& p1_;
  mutable bool has_normal_ = false;
  mutable Vector3d n0_, n1_, n2_;
  mutable double normal_scale_ = 0;
};

/// The values u·x of a triangle's three corners.
std::array<double, 3> along(const Vector3d& u, const TriangleCorners& x) { return {u.dot(x[0]), u.dot(x[1]), u.dot(x[2])}; }

/// How far X reaches above the lowest point of Y along u (X below Y when ≤ δ), from their
/// corners' values along u.
double overlap(const std::array<double, 3>& x, const std::array<double, 3>& y) {
  return std::max({x[0], x[1], x[2]}) - std::min({y[0], y[1], y[2]});
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

/// Whether each of X (below) and Y (above along u) that may lie flat in the separating band
/// faces the right way over [s_lo, s_hi]: X's normal never points down, Y's never up.
bool facing_apart(const Vector3d& u, const Moving& x, const Moving& y, double s_lo, double s_hi, double delta) {
  const double band = 2 * delta;
  if (!thick_throughout(u, x, band) && x.highest_facing(-u, s_lo, s_hi) > x.facing_slack()) return false;
  return thick_throughout(u, y, band) || y.highest_facing(u, s_lo, s_hi) <= y.facing_slack();
}

/// Whether direction u certifies that A and B only touch over [s_lo, s_hi]: one stays below
/// the other along u, overlapping by at most δ at both ends, and faces the right way
/// (`facing_apart`). The corners' values along u are taken once for both ways round; at an
/// instant (s_lo = s_hi) the ends are one.
bool certifies(const Vector3d& u, const Moving& a, const Moving& b, double s_lo, double s_hi, double delta) {
  const std::array<double, 3> a_lo = along(u, a.lo), b_lo = along(u, b.lo);
  const bool instant = s_lo == s_hi;
  std::array<double, 3> a_hi{}, b_hi{};
  bool hi_known = instant;
  const auto below = [&](const Moving& x, const std::array<double, 3>& x_lo, const std::array<double, 3>& x_hi,
                         const Moving& y, const std::array<double, 3>& y_lo, const std::array<double, 3>& y_hi) {
    if (overlap(x_lo, y_lo) > delta) return false;
    if (!hi_known) {
      a_hi = along(u, a.hi);
      b_hi = along(u, b.hi);
      hi_known = true;
    }
    if (!instant && overlap(x_hi, y_hi) > delta) return false;
    return facing_apart(u, x, y, s_lo, s_hi, delta);
  };
  return below(a, a_lo, a_hi, b, b_lo, b_hi) || below(b, b_lo, b_hi, a, a_lo, a_hi);
}

/// Whether the triangles only touch at step parameter s, computed once per instant.
enum class Instant : signed char { kUnknown, kTouching, kInterfering };

/// Halves pieces where touching cannot be certified (`interference_pieces`), each instant's
/// verdict computed once and shared by the pieces that end there.
struct PieceClassifier {
  const TriangleCorners &a0, &a1, &b0, &b1;
  double delta;
  std::vector<TimeInterval>& out;

  bool interferes_at(double s, Instant& known) const {
    if (known == Instant::kUnknown)
      known = touching_throughout(a0, a1, b0, b1, s, s, delta) ? Instant::kTouching : Instant::kInterfering;
    return known == Instant::kInterfering;
  }

  /// `at_lo`, `at_hi`: what is known of the instants lo and hi (filled in where computed).
  void classify(double lo, double hi, Instant& at_lo, Instant& at_hi, int depth) const {
    // Interfering at both ends: kept whole (only its ends matter to the intervals, and those
    // are refined by re-detection), without trying to certify it.
    const bool ends_interfere = interferes_at(lo, at_lo) && interferes_at(hi, at_hi);
    if (!ends_interfere && touching_throughout(a0, a1, b0, b1, lo, hi, delta)) return;
    const double mid = 0.5 * (lo + hi);
    if (depth == 0 || ends_interfere || !(lo < mid && mid < hi)) {
      out.push_back({lo, hi});
      return;
    }
    Instant at_mid = Instant::kUnknown;
    classify(lo, mid, at_lo, at_mid, depth - 1);
    classify(mid, hi, at_mid, at_hi, depth - 1);
  }
};

}  // namespace

bool touching_throughout(const TriangleCorners& a0, const TriangleCorners& a1, const TriangleCorners& b0,
                         const TriangleCorners& b1, double lo, double hi, double delta) {
  const Moving a(a0, a1, lo, hi), b(b0, b1, lo, hi);
  const Axes axes = separating_axes(a.mid, b.mid);
  for (int i = 0; i < axes.count; ++i)
    if (certifies(axes.axis[i], a, b, lo, hi, delta)) return true;
  return false;
}

bool triangles_touch(const TriangleCorners& a, const TriangleCorners& b, double delta) {
  return touching_throughout(a, a, b, b, 0, 0, delta);
}

std::vector<TimeInterval> interference_pieces(const TriangleCorners& a0, const TriangleCorners& a1,
                                              const TriangleCorners& b0, const TriangleCorners& b1,
                                              const std::vector<TimeInterval>& pieces, double delta, int depth) {
  std::vector<TimeInterval> out;
  const PieceClassifier classifier{a0, a1, b0, b1, delta, out};
  Instant at_end = Instant::kUnknown;  // the last piece's end, shared by a piece starting there
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    Instant at_start = i > 0 && pieces[i].lo == pieces[i - 1].hi ? at_end : Instant::kUnknown;
    at_end = Instant::kUnknown;
    classifier.classify(pieces[i].lo, pieces[i].hi, at_start, at_end, depth);
  }
  return out;
}

}  // namespace reconfig::collision
