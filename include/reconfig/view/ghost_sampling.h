#pragma once
/// @file
/// Ghost sampling: which instants of a transition to show as transparent copies around the
/// current time, and how strongly (reconfigurables §5, "ghosting").

#include <vector>

namespace reconfig::view {

struct GhostRequest {
  double current = 0;    ///< the time shown solid, in [0, 1]
  int count = 3;         ///< ghosts on each requested side of `current` (≥ 0)
  double spacing = 0.1;  ///< time between consecutive ghosts (> 0)
  bool past = true;      ///< ghosts at current − k · spacing
  bool future = true;    ///< ghosts at current + k · spacing
};

/// One ghost: a time and a weight in (0, 1] (opacity scale) that fades with the distance
/// to the current time: the k-th ghost on a side (k = 1 … count) weighs 1 − (k − 1) / count.
struct GhostSample {
  double time = 0;
  double weight = 0;
};

/// The ghosts of `request`, ascending in time; times outside [0, 1] are dropped (a ghost
/// never repeats the pose held before the start or after the end).
std::vector<GhostSample> ghost_samples(const GhostRequest& request);

}  // namespace reconfig::view
