#include "reconfig/resolve/interval_energy.h"

#include <algorithm>

#include "reconfig/collision/detector_settings.h"
#include "reconfig/resolve/proximity.h"

namespace reconfig::resolve {

IntervalEnergy interval_energy(const scene::Reconfigurable& scene, ShapeCache& shapes, int transition,
                               const collision::CollisionInterval& interval, double time_margin, int part,
                               std::optional<double> proximity_reach) {
  const double reach = proximity_reach ? *proximity_reach : resolve::proximity_reach(collision::with_settings({}, scene.collision));
  std::vector<std::array<int, 2>> pairs;
  for (std::size_t i = 0; i < interval.parts.size(); ++i)
    for (std::size_t j = i + 1; j < interval.parts.size(); ++j) {
      const int a = interval.parts[i], b = interval.parts[j];
      if (part < 0) pairs.push_back({a, b});
      else if (a == part) pairs.push_back({a, b});
      else if (b == part) pairs.push_back({b, a});
    }
  IntervalEnergy result;
  double largest = -1;
  for (const auto& pair : pairs) {
    PairEnergyRequest request;
    request.transition = transition;
    request.part_a = pair[0];
    request.part_b = pair[1];
    request.t0 = std::max(0.0, interval.t0 - time_margin);
    request.t1 = std::min(1.0, interval.t1 + time_margin);
    request.proximity_reach = reach;
    PairEnergy energy = pair_energy(scene, shapes, request);
    result.energy += energy.energy;
    result.contour_energy += energy.contour_energy;
    result.penetration_energy += energy.penetration_energy;
    result.proximity_energy += energy.proximity_energy;
    if (energy.energy > largest) {
      largest = energy.energy;
      result.severity_time = energy.severity_time;
    }
    result.pairs.emplace_back(pair, std::move(energy));
  }
  if (pairs.empty()) result.severity_time = 0.5 * (interval.t0 + interval.t1);
  return result;
}

}  // namespace reconfig::resolve
