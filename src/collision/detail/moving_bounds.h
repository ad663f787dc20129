#pragma once
/// @file
/// Bounds of geometry that moves linearly over one proxy step: where, and when within the step,
/// two moving triangles or two tree nodes (given their k-DOPs at the step's ends) can meet.

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "reconfig/collision/kdop.h"

namespace reconfig::collision::detail {

/// A triangle's corners at one time.
using MovingTriangle = std::array<Eigen::Vector3d, 3>;

/// The box of a triangle moving linearly from `p0` to `p1` over the fractions [mu0, mu1] of
/// its step.
inline Eigen::AlignedBox3d triangle_box_at(const MovingTriangle& p0, const MovingTriangle& p1, double mu0, double mu1) {
  Eigen::Vector3d lo, hi;
  for (int axis = 0; axis < 3; ++axis) {
    double l = std::numeric_limits<double>::infinity(), h = -l;
    for (int c = 0; c < 3; ++c)
      for (const double mu : {mu0, mu1}) {
        const double x = (1 - mu) * p0[c][axis] + mu * p1[c][axis];
        l = std::min(l, x);
        h = std::max(h, x);
      }
    lo[axis] = l;
    hi[axis] = h;
  }
  return {lo, hi};
}

/// The pieces k (bit k) of `kCullPieces` equal pieces of a time step where the spacetime
/// k-DOPs of two moving triangles, A's grown by `reach`, meet: the hull of a triangle's sweep
/// over a whole step is much looser when it moves further than its size. Axis projections
/// of a vertex are affine in time, so they are interpolated from those at the step's ends;
/// the time component of an axis is the same for both triangles over a piece, so only the
/// spatial part matters.
inline constexpr int kCullPieces = 8;

/// The narrow phase refines a step down to this many equal pieces (dyadic: they nest within the
/// `kCullPieces`), and reports a piece whole when a contact event lies in it.
inline constexpr int kNarrowPieces = 32;

template <DopFamily family>
unsigned meeting_pieces(const MovingTriangle& a0, const MovingTriangle& a1, const MovingTriangle& b0,
                        const MovingTriangle& b1, double reach) {
  constexpr int K = Kdop<family>::kAxes;
  using Axes = Eigen::Matrix<double, K, 1>;
  // Every corner's values along every axis at the step's ends (the time term is left out).
  std::array<Axes, 3> pa[2], pb[2];
  for (int c = 0; c < 3; ++c) {
    pa[0][c] = axis_values<family>(a0[c], 0), pa[1][c] = axis_values<family>(a1[c], 0);
    pb[0][c] = axis_values<family>(b0[c], 0), pb[1][c] = axis_values<family>(b1[c], 0);
  }
  static const Axes kAxisLengths = [] {  // of the axes' spatial parts
    Axes lengths;
    for (int j = 0; j < K; ++j) lengths[j] = dop_axes<family>()[j].template head<3>().norm();
    return lengths;
  }();
  const Axes grow = reach * kAxisLengths;
  // Over the whole step first: a pair apart along some axis throughout needs no pieces.
  {
    Axes lo_a = pa[0][0], hi_a = pa[0][0], lo_b = pb[0][0], hi_b = pb[0][0];
    for (int end = 0; end < 2; ++end)
      for (int c = 0; c < 3; ++c) {
        lo_a = lo_a.cwiseMin(pa[end][c]), hi_a = hi_a.cwiseMax(pa[end][c]);
        lo_b = lo_b.cwiseMin(pb[end][c]), hi_b = hi_b.cwiseMax(pb[end][c]);
      }
    if (((lo_a - grow).array() > hi_b.array()).any() || (lo_b.array() > (hi_a + grow).array()).any()) return 0;
  }
  // Every axis at once: the range of each triangle's projections at each piece boundary (a
  // piece's range spans its two ends).
  std::array<Axes, kCullPieces + 1> lo_a, hi_a, lo_b, hi_b;
  for (int k = 0; k <= kCullPieces; ++k) {
    const double mu = static_cast<double>(k) / kCullPieces;
    const auto at = [&](const std::array<Axes, 3>(&p)[2], int c) -> Axes { return (1 - mu) * p[0][c] + mu * p[1][c]; };
    lo_a[k] = hi_a[k] = at(pa, 0);
    lo_b[k] = hi_b[k] = at(pb, 0);
    for (int c = 1; c < 3; ++c) {
      const Axes va = at(pa, c), vb = at(pb, c);
      lo_a[k] = lo_a[k].cwiseMin(va), hi_a[k] = hi_a[k].cwiseMax(va);
      lo_b[k] = lo_b[k].cwiseMin(vb), hi_b[k] = hi_b[k].cwiseMax(vb);
    }
  }
  unsigned meeting = 0;
  for (int k = 0; k < kCullPieces; ++k) {
    const Axes a_lo = lo_a[k].cwiseMin(lo_a[k + 1]) - grow, a_hi = hi_a[k].cwiseMax(hi_a[k + 1]) + grow;
    const Axes b_lo = lo_b[k].cwiseMin(lo_b[k + 1]), b_hi = hi_b[k].cwiseMax(hi_b[k + 1]);
    if (!((a_lo.array() > b_hi.array()).any() || (b_lo.array() > a_hi.array()).any())) meeting |= 1u << k;
  }
  return meeting;
}

/// The fractions μ ∈ [0, 1] of a step during which two nodes may meet, given their k-DOPs at
/// the step's ends (`a`, `b`); empty (first > second) if they cannot. Along every axis a point's
/// projection moves linearly over the step, so the lowest projection of a set of points is
/// concave in μ (and the highest convex): it stays above the line between its values at the
/// ends (the highest below). Where those lines of A and B leave a gap along some axis, the
/// nodes cannot meet.
template <DopFamily family>
std::pair<double, double> meeting_range(const std::array<Kdop<family>, 2>& a, const std::array<Kdop<family>, 2>& b) {
  constexpr double kSlack = 1e-9;  // absorbs the rounding of the crossing points
  double first = 0, last = 1;
  // Keeps the μ where f (linear, f0 at 0 and f1 at 1) is at most 0.
  const auto keep_nonpositive = [&](double f0, double f1) {
    if (f0 <= 0 && f1 <= 0) return;
    if (f0 > 0 && f1 > 0) {
      first = 1, last = 0;
      return;
    }
    const double crossing = f0 / (f0 - f1);
    if (f0 > 0) first = std::max(first, crossing - kSlack);
    else last = std::min(last, crossing + kSlack);
  };
  for (int j = 0; j < Kdop<family>::kAxes && first <= last; ++j) {
    keep_nonpositive(a[0].lo[j] - b[0].hi[j], a[1].lo[j] - b[1].hi[j]);
    keep_nonpositive(b[0].lo[j] - a[0].hi[j], b[1].lo[j] - a[1].hi[j]);
  }
  return {std::max(first, 0.0), std::min(last, 1.0)};
}

/// The spatial box of a k-DOP: its first three axes are x, y and z in every family.
template <DopFamily family>
Eigen::AlignedBox3d spatial_box(const Kdop<family>& dop) {
  return {Eigen::Vector3d(dop.lo[0], dop.lo[1], dop.lo[2]), Eigen::Vector3d(dop.hi[0], dop.hi[1], dop.hi[2])};
}

}  // namespace reconfig::collision::detail
