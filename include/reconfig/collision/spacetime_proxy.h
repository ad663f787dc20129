#pragma once
/// @file
/// Spacetime proxies: each part's vertex paths, piecewise linear between time samples chosen
/// from the motion so that the proxy never strays further than a tolerance from the true rigid
/// motion (reconfigurables §3, with adaptive instead of fixed Δt).

#include <Eigen/Geometry>
#include <optional>
#include <utility>
#include <vector>

#include "reconfig/scene/reconfigurable.h"

namespace reconfig::collision {

/// The proxy of one part over one transition: rigid maps at sample times; between two
/// samples every vertex moves on the straight segment joining its two sampled positions.
struct PartProxy {
  std::vector<double> times;              ///< 0 = τ_0 < τ_1 < … < τ_m = 1
  std::vector<Eigen::Isometry3d> poses;   ///< world = poses[k] · rest, at times[k]
  /// A bound on the distance between any vertex's proxy path and its true path: at most the
  /// requested tolerance (unless a step hit the minimum step size, then the bound reached).
  double deviation = 0;
  bool moving = false;  ///< false if the part holds one pose during the whole transition

  /// Index k of the step [τ_k, τ_{k+1}] that contains t (the last step for t = 1).
  int step_of(double t) const;
};

/// Chooses the samples of `part` in `transition`: a part that holds still gets the two ends;
/// a moving part gets steps such that its deviation bound over every step (the motion
/// module's bounds, with the radius of the part around its center) is ≤ `tolerance`.
/// @param tolerance  > 0, in scene units
/// @param min_step   smallest step the subdivision produces (guards against unbounded motions)
PartProxy build_part_proxy(const scene::Reconfigurable& scene, int transition, int part, double tolerance,
                           double min_step = 1e-5);

/// The time range over which two proxies of the same part differ: from the last sample of
/// their common beginning to the first sample of their common end (both are samples of
/// both). Empty if they are identical.
std::optional<std::pair<double, double>> changed_range(const PartProxy& before, const PartProxy& after);

}  // namespace reconfig::collision
