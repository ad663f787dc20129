#pragma once
/// @file
/// Conservative bounds on how far the points of a moving part stray from straight-line
/// motion over a time interval. The collision engine uses them to choose time steps so that
/// a piecewise-linear spacetime proxy never strays further than a tolerance from the true
/// motion.

#include "reconfig/motion/bezier_translation_track.h"
#include "reconfig/motion/screw_track.h"
#include "reconfig/motion/slerp_rotation_track.h"

#include <functional>
#include <vector>

namespace reconfig::motion {

/// Bounds for every point p with |p − c| <= radius (c: the part's center) over [t0, t1].
struct MotionBound {
  /// |v(t) − L(t)| <= deviation for all t ∈ [t0, t1], where v(t) is the point's position
  /// and L(t) = ((t1 − t) v(t0) + (t − t0) v(t1)) / (t1 − t0) is the linear interpolation of
  /// its end positions in time.
  double deviation = 0.0;
  /// |v(t) − v(t0)| <= displacement for all t ∈ [t0, t1].
  double displacement = 0.0;
};

/// Bounds for a part moving by a Bézier translation track x and a slerp rotation track R,
/// v(t) = R(t)(p − c) + c + x(t).
///
/// Derivation. v − L splits into (x − L_x) + (R − L_R)(p − c), so
/// deviation <= sup|x − L_x| + radius · sup‖R − L_R‖₂. The interval is cut at the key times
/// it contains. On a piece, x is a cubic Bézier (restricted by blossoming to control points
/// Q0..Q3); its distance to its own chord is 3f(1−f)²a + 3f²(1−f)b with a = Q1 − (2Q0+Q3)/3,
/// b = Q2 − (Q0+2Q3)/3, bounded by maximizing 3f(1−f)((1−f)|a| + f|b|) exactly. A slerp
/// piece turning by ψ differs from its matrix chord by at most min(ψ²/8, 2) in operator
/// norm (the deviation of a uniform unit-circle arc from its uniform chord has second
/// derivative of modulus ψ²). Between a piece's chord and the whole interval's chord the
/// difference is linear in t, so it is bounded by its values at the breakpoints, which are
/// computed exactly. displacement <= max over pieces of max_k |Q_k − x(t0)| (convex hull)
/// + radius · 2 sin(min(Ψ, π)/2), Ψ the total angle turned.
/// @param translation  the translation track
/// @param rotation     the rotation track
/// @param radius       r >= 0, radius of the ball about the center that holds the points
/// @param t0, t1       interval, t0 <= t1 (may extend outside the tracks' key times)
MotionBound keyframed_motion_bound(const BezierTranslationTrack& translation,
                                   const SlerpRotationTrack& rotation, double radius, double t0,
                                   double t1);

/// Bounds for a part moving along a piecewise screw track, v(t) = M(t) p.
///
/// Derivation. v = M(t)c + R_M(t)(p − c): the center moves on a helix and the rest turns
/// with the screw's rotation. On a piece of screw j turning by ψ = b_j Δf, the center's
/// helix has radius ρ about the axis; along the axis it advances linearly (no deviation)
/// and across it it runs on a circle arc, so it strays at most ρ · min(ψ²/8, 2) from its
/// chord; ρ is obtained from the chord ℓ of the whole segment as ℓ / (2 sin(b/2)) in a form
/// that stays finite as b → 0. The rotation term and the breakpoint terms are as for
/// `keyframed_motion_bound`. displacement <= the helix arc length of the center
/// (√(d² + (ρ b)²) per unit of segment parameter) + radius · 2 sin(min(Ψ, π)/2).
/// @param track   the screw track (its center is the c above)
/// @param radius  r >= 0
/// @param t0, t1  interval, t0 <= t1
MotionBound screw_motion_bound(const ScrewTrack& track, double radius, double t0, double t1);

/// The samples `adaptive_time_samples` chooses, and the largest deviation bound over their steps.
struct AdaptiveSamples {
  std::vector<double> times;  ///< t0 = τ_0 < τ_1 < ... < τ_m = t1
  double deviation = 0.0;     ///< max over the steps of `deviation_bound(τ_i, τ_{i+1})`
};

/// Times t0 = τ_0 < τ_1 < ... < τ_m = t1 such that `deviation_bound(τ_i, τ_{i+1})` <=
/// tolerance on every step, found by recursive bisection; a step narrower than `min_step`
/// is accepted as it is (so the result is finite even if the bound never gets small: the
/// reported deviation then exceeds the tolerance). Every step's bound is evaluated exactly once.
/// Deterministic. Typical use:
/// `adaptive_time_samples([&](double a, double b) { return screw_motion_bound(track, r, a, b).deviation; }, 0, 1, 1e-3)`.
/// @param deviation_bound  (a, b) ↦ bound on the deviation over [a, b]
/// @param t0, t1           interval, t0 <= t1
/// @param tolerance        > 0
/// @param min_step         > 0, smallest step the bisection produces
AdaptiveSamples adaptive_time_samples(const std::function<double(double, double)>& deviation_bound, double t0,
                                      double t1, double tolerance, double min_step = 1e-6);

}  // namespace reconfig::motion
