#pragma once
/// @file
/// The time step a user of a discrete collision checker (FCL) needs to make the engine's
/// promise: between two consecutive samples no vertex of any part moves more than the
/// tolerance, so a collision of the true continuous motion cannot hide between them.

#include <vector>

#include "reconfig/scene/reconfigurable.h"

namespace reconfig::bench {

/// Uniform samples of one transition fine enough for the tolerance.
struct GuaranteedSamples {
  std::vector<double> times;  ///< k / n for k = 0 … n (n ≥ 1)
  /// Largest bound, over the moving parts and the steps, on how far a vertex moves within
  /// one step (the motion module's `MotionBound::displacement` with the part's radius): ≤ the
  /// tolerance.
  double max_displacement = 0;
};

/// Bound on how far any vertex of `part` moves from where it is at time a during [a, b] of
/// `transition` (0 for a part without a track): the motion module's displacement bound, the
/// one the engine's proxies use for deviations, with the radius of the part about its center.
double vertex_displacement_bound(const scene::Reconfigurable& scene, int transition, int part, double a, double b);

/// The coarsest uniform sampling k / n of [0, 1] such that, on every step and for every moving
/// part, `vertex_displacement_bound` ≤ `tolerance`: a vertex moving at speed s (translation
/// speed plus angular speed × radius) needs n ≈ s / tolerance.
/// @param tolerance  > 0, in scene units
GuaranteedSamples guaranteed_samples(const scene::Reconfigurable& scene, int transition, double tolerance);

}  // namespace reconfig::bench
