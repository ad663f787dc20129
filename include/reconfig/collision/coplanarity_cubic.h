#pragma once
/// @file
/// A cheap, certified exclusion filter for the contact tests of the narrow phase: four
/// linearly moving points that never become coplanar over a time range cannot touch there.
///
/// A vertex p touching a triangle (a, b, c), or an edge (a, b) touching an edge (c, d), makes
/// the four points coplanar: o(t) = det[x₁(t) − x₀(t), x₂(t) − x₀(t), x₃(t) − x₀(t)] = 0. With
/// every point moving linearly, o is a cubic in t; over [t_min, t_max] its Bernstein
/// coefficients follow from the three difference vectors at the two ends (o is trilinear in
/// them), and the cubic lies in their convex hull. When all four coefficients have one sign,
/// by more than a proven bound on rounding, o has no root there: no contact of any kind, for
/// any triangle or segment shapes (degenerate ones included). A few dozen multiplications,
/// against hundreds of boxes for an inclusion test (`ccd_primitives.h`) that has to look for
/// the contact; coplanar or nearly coplanar motions are simply not excluded. Halving the range
/// needs no new determinants: the halves' coefficients follow by de Casteljau's midpoints,
/// and the error bound grows by a few roundings of the largest coefficient.

#include <Eigen/Core>
#include <array>
#include <cmath>

#include "reconfig/collision/ccd_primitives.h"

namespace reconfig::collision {

/// Four moving points: point k is at `start[k]` at t = 0 and at `end[k]` at t = 1, and at
/// start + t (end − start) in between.
struct MovingPoints {
  std::array<Eigen::Vector3d, 4> start, end;
};

/// What the bound can tell about the four points over its time range.
enum class Coplanarity {
  kNever,    ///< never coplanar over the range (robust, see `CoplanarityCubic`)
  kInside,   ///< perhaps coplanar somewhere, but not at either end of the range
  kAtAnEnd,  ///< perhaps coplanar at an end of the range (or throughout, as when they translate together)
};

/// The coplanarity cubic of four moving points over a time range, in Bernstein form with a
/// proven error bound. Its verdicts are robust: they still hold when every point is moved by
/// up to `kRobustPerturbation` × M in each coordinate at any time (M = largest absolute input
/// coordinate), like the "no" of the contact tests.
class CoplanarityCubic {
 public:
  /// A cubic that excludes nothing.
  CoplanarityCubic() = default;
  /// The cubic over [t_min, t_max] ⊂ [0, 1]. Non-finite or huge (≥ 2^300) coordinates give a
  /// cubic that excludes nothing.
  CoplanarityCubic(const MovingPoints& points, double t_min, double t_max);

  /// Whether the points may be coplanar at some time of the range (never `kNever` if they are);
  /// `kInside` guarantees that they are not at either end.
  Coplanarity classify() const;

  /// The cubic over the first and the second half of the range, split at its exact middle
  /// (t_min + t_max) / 2: callers must make sure that this middle is a double (as it is for
  /// dyadic ranges down to 2^-52), or build the halves' cubics afresh.
  std::array<CoplanarityCubic, 2> halves() const;

 private:
  std::array<double, 4> coefficients_{};  ///< Bernstein coefficients, computed
  double error_ = HUGE_VAL;                    ///< bound on their distance to the perturbed cubic's
};

}  // namespace reconfig::collision
