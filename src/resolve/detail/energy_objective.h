#pragma once
/// @file
/// What automatic resolution minimizes: the energy of some pairs of parts over time windows.

#include <utility>
#include <vector>

#include "reconfig/resolve/pair_energy.h"
#include "reconfig/resolve/shape_cache.h"
#include "reconfig/scene/reconfigurable.h"

namespace reconfig::resolve::detail {

using Pair = std::pair<int, int>;
using Window = std::pair<double, double>;

/// Pairs of parts, each over time windows: first the pair being resolved, whose windows come
/// from detected intervals and so include the proximity term (`proximity.h`), then the pairs
/// its moves may run into, without it (parts resting on each other would keep a deficit).
struct EnergyObjective {
  int transition = 0;
  std::vector<std::pair<Pair, std::vector<Window>>> pairs;
  double proximity_reach = 0;  ///< of the first pair's energy (0: none)
};

/// One pair over one window.
struct ObjectiveTerm {
  Pair pair;
  PairEnergy energy;
};

struct ObjectiveEnergy {
  double energy = 0;
  double severity_time = 0;  ///< of the most energetic term
  std::vector<ObjectiveTerm> terms;
};

ObjectiveEnergy evaluate(const EnergyObjective& objective, const scene::Reconfigurable& scene, ShapeCache& shapes);

/// The pair's own windows, plus each movable part against every other part it may reach over
/// those windows (boxes of the parts' poses at 33 times, the movable ones widened by `reach`):
/// a move that resolves the pair by pushing a part into a third one does not lower this.
EnergyObjective resolution_objective(const scene::Reconfigurable& scene, int transition, Pair pair,
                                     const std::vector<Window>& windows, const std::vector<int>& movable, double reach,
                                     double proximity_reach);

}  // namespace reconfig::resolve::detail
