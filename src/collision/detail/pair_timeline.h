#pragma once
/// @file
/// Pair timelines: two parts of a pair placed at the merged sample times of their proxies over
/// a time range, so that on every step between consecutive times both parts' vertices move
/// linearly (the unit the traversal bounds and searches), and the proxy placements behind them.

#include <algorithm>
#include <vector>

#include "collision/detail/sample_axes.h"
#include "reconfig/collision/spacetime_proxy.h"

namespace reconfig::collision::detail {

/// The map a fraction s ∈ [0, 1] of the way from p0 to p1.
Affine interpolate(const Affine& p0, const Affine& p1, double s);

/// A part's proxy placement at time t (linear between its samples, held outside them).
Affine proxy_map(const PartProxy& proxy, double t);

/// Both parts of a pair placed at the merged sample times of their proxies over a range:
/// on every step between consecutive times both parts' vertices move linearly.
struct PairTimeline {
  int a = 0, b = 0;
  std::vector<double> times;
  std::vector<Affine> maps[2];
  bool moving[2] = {false, false};  ///< some map differs from the first

  /// The step [times[k], times[k + 1]] holding t (the first or last step outside the range),
  /// as `PartProxy::step_of`.
  int step_of(double t) const {
    const int k = static_cast<int>(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
    return std::clamp(k, 0, static_cast<int>(times.size()) - 2);
  }
};

/// The timeline of parts a and b over [t0, t1]: t0, t1 and every sample of either proxy between.
PairTimeline merged_timeline(const std::vector<PartProxy>& proxies, int a, int b, double t0, double t1);

}  // namespace reconfig::collision::detail
