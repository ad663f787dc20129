#include "reconfig/collision/coplanarity_cubic.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "collision/detail/determinant.h"

namespace reconfig::collision {
namespace {

using detail::det3;

constexpr double kEpsilon = 0x1p-53;

}  // namespace

/// Error analysis (ε = 2^-53, M = largest |input coordinate|, first-order terms; the final
/// doubling absorbs the rest). Positions x(t) = x0 + t (x1 − x0) are computed within 6εM, so
/// the difference vectors within 15εM of their exact values; the robust perturbation moves
/// them by ≤ 2 · 6εM more. With D' ≥ every |component| of the exact, computed and perturbed
/// vectors, a determinant (6 products of 3 components) changes by ≤ 18 D'² δ when every
/// component moves by ≤ δ: ≤ 270 εM D'² from the computed inputs, ≤ 216 εM D'² from the
/// perturbation (the cubic at every t ∈ [t_min, t_max], a convex combination of exact
/// coefficients, stays within that of its exact value). Evaluating a determinant as x · (y × z)
/// costs ≤ 30 εD'³, an average of three ≤ 48 εD'³. So a computed coefficient differs from the
/// perturbed cubic's coefficient by ≤ 64 εD'³ + 512 εM D'², doubled below; the guard covers
/// underflow (≤ 2^-1074 per operation). The end coefficients are the cubic's values at the ends.
CoplanarityCubic::CoplanarityCubic(const MovingPoints& points, double t_min, double t_max) {
  assert(0 <= t_min && t_min <= t_max && t_max <= 1);
  double m = 0;
  for (int k = 0; k < 4; ++k) m = std::max({m, points.start[k].cwiseAbs().maxCoeff(), points.end[k].cwiseAbs().maxCoeff()});
  if (!(m < 0x1p300)) {  // also NaN
    error_ = HUGE_VAL;
    return;
  }

  // Difference vectors v[end][j] = x_{j+1} − x_0 at t_min (end 0) and t_max (end 1).
  double v[2][3][3];
  double d = 0;
  for (int e = 0; e < 2; ++e) {
    const double t = e == 0 ? t_min : t_max;
    double x[4][3];
    for (int k = 0; k < 4; ++k)
      for (int i = 0; i < 3; ++i) x[k][i] = points.start[k][i] + t * (points.end[k][i] - points.start[k][i]);
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        v[e][j][i] = x[j + 1][i] - x[0][i];
        d = std::max(d, std::abs(v[e][j][i]));
      }
  }
  const double dp = d + 32 * kEpsilon * m;
  error_ = 2 * (64 * kEpsilon * dp * dp * dp + 512 * kEpsilon * m * dp * dp) + 0x1p-1000;

  const auto& [x0, y0, z0] = v[0];
  const auto& [x1, y1, z1] = v[1];
  coefficients_ = {det3(x0, y0, z0), (det3(x1, y0, z0) + det3(x0, y1, z0) + det3(x0, y0, z1)) / 3,
                   (det3(x0, y1, z1) + det3(x1, y0, z1) + det3(x1, y1, z0)) / 3, det3(x1, y1, z1)};
}

Coplanarity CoplanarityCubic::classify() const {
  const auto& b = coefficients_;
  const double e = error_;
  if (!(std::abs(b[0]) > e && std::abs(b[3]) > e)) return Coplanarity::kAtAnEnd;
  const bool positive = b[0] > e && b[1] > e && b[2] > e && b[3] > e;
  const bool negative = b[0] < -e && b[1] < -e && b[2] < -e && b[3] < -e;
  return positive || negative ? Coplanarity::kNever : Coplanarity::kInside;
}

/// De Casteljau at 1/2: every new coefficient is a chain of at most three midpoints of
/// values bounded by B = max |b_i|, each rounded by ≤ εB; the exact halves' coefficients are
/// the same midpoints of the exact coefficients, so the error grows by ≤ 3εB (4εB below).
std::array<CoplanarityCubic, 2> CoplanarityCubic::halves() const {
  const auto& b = coefficients_;
  const double b01 = 0.5 * (b[0] + b[1]), b12 = 0.5 * (b[1] + b[2]), b23 = 0.5 * (b[2] + b[3]);
  const double b012 = 0.5 * (b01 + b12), b123 = 0.5 * (b12 + b23);
  const double middle = 0.5 * (b012 + b123);
  const double largest = std::max({std::abs(b[0]), std::abs(b[1]), std::abs(b[2]), std::abs(b[3])});
  std::array<CoplanarityCubic, 2> halves;
  halves[0].coefficients_ = {b[0], b01, b012, middle};
  halves[1].coefficients_ = {middle, b123, b23, b[3]};
  halves[0].error_ = halves[1].error_ = error_ + 4 * kEpsilon * largest + 0x1p-1000;
  return halves;
}

}  // namespace reconfig::collision
