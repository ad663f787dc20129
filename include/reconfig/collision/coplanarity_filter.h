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
/// the contact; coplanar or nearly coplanar motions are simply not excluded.

#include <Eigen/Core>
#include <array>

#include "reconfig/collision/ccd_primitives.h"

namespace reconfig::collision {

/// Four moving points: point k is at `start[k]` at t = 0 and at `end[k]` at t = 1, and at
/// start + t (end − start) in between.
struct MovingPoints {
  std::array<Eigen::Vector3d, 4> start, end;
};

/// What the filter can tell about the four points over a time range.
enum class Coplanarity {
  kNever,    ///< never coplanar over the range (robust, see below)
  kInside,   ///< perhaps coplanar somewhere, but not at either end of the range
  kAtAnEnd,  ///< perhaps coplanar at an end of the range (or throughout, as when they translate together)
};

/// Whether the four points may be coplanar at some time of [t_min, t_max] ⊂ [0, 1] (never
/// `kNever` if they are). A `kNever` is robust: it still holds when every point is moved by up
/// to `kRobustPerturbation` × M in each coordinate at any time (M = largest absolute input
/// coordinate), like the "no" of the contact tests; likewise "not at either end" for
/// `kInside`. Non-finite or huge (≥ 2^300) coordinates give `kAtAnEnd`.
Coplanarity coplanarity(const MovingPoints& points, double t_min, double t_max);

}  // namespace reconfig::collision
