#pragma once
/// @file
/// The intersection energy of one collision interval: the sum over its pairs of parts.

#include <array>
#include <optional>
#include <vector>

#include "reconfig/collision/collision_interval.h"
#include "reconfig/resolve/pair_energy.h"
#include "reconfig/resolve/shape_cache.h"
#include "reconfig/scene/reconfigurable.h"

namespace reconfig::resolve {

struct IntervalEnergy {
  double energy = 0;              ///< Σ over the pairs of their E (pair_energy.h)
  double contour_energy = 0;      ///< Σ ∫ ‖Ic‖ dt (the paper's eq. 1)
  double penetration_energy = 0;  ///< Σ ∫ P dt
  double proximity_energy = 0;    ///< Σ ∫ D dt
  double severity_time = 0;       ///< the most energetic pair's
  /// Each pair (part a, part b) with its energy and samples.
  std::vector<std::pair<std::array<int, 2>, PairEnergy>> pairs;
};

/// The energy of `interval` of `transition` over its time extent widened by `time_margin` on
/// both sides (clipped to [0, 1]): the interval's ends are exact (to the detector's time
/// error), and the margin keeps the approach and the departure, where only the proximity term
/// is non-zero, inside the integral. With `part` ≥ 0 only the pairs (part, other) are summed,
/// `part` being each pair's part a. The proximity term's reach is `proximity_reach` if given,
/// else that of the design's own detector settings (`proximity.h`): pass the detector's when it
/// was run with other settings.
IntervalEnergy interval_energy(const scene::Reconfigurable& scene, ShapeCache& shapes, int transition,
                               const collision::CollisionInterval& interval, double time_margin = 0.01, int part = -1,
                               std::optional<double> proximity_reach = std::nullopt);

}  // namespace reconfig::resolve
