#include "resolve/detail/energy_objective.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <set>

#include "reconfig/geometry/bounding_box.h"

namespace reconfig::resolve::detail {
namespace {

constexpr int kBoxSamples = 33;

/// The box around a part's posed rest box at evenly spaced times over the windows.
Eigen::AlignedBox3d swept_box(const scene::Reconfigurable& scene, int transition, int part,
                              const std::vector<Window>& windows) {
  const scene::Part& p = scene.parts[part];
  const Eigen::AlignedBox3d rest = geometry::bounding_box(p.mesh.V);
  Eigen::AlignedBox3d box;
  for (const Window& w : windows)
    for (int i = 0; i < kBoxSamples; ++i) {
      const double t = w.first + (w.second - w.first) * i / (kBoxSamples - 1);
      const Eigen::Isometry3d place = scene.pose_at(transition, part, t).to_isometry(p.center);
      for (int c = 0; c < 8; ++c) box.extend(place * rest.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)));
    }
  return box;
}

}  // namespace

ObjectiveEnergy evaluate(const EnergyObjective& objective, const scene::Reconfigurable& scene, ShapeCache& shapes) {
  ObjectiveEnergy result;
  double largest = -1;
  for (const auto& [pair, windows] : objective.pairs)
    for (const Window& w : windows) {
      const bool first = &pair == &objective.pairs.front().first;
      PairEnergyRequest request;
      request.transition = objective.transition;
      request.part_a = pair.first;
      request.part_b = pair.second;
      request.t0 = w.first;
      request.t1 = w.second;
      request.proximity_reach = first ? objective.proximity_reach : 0.0;
      PairEnergy energy = pair_energy(scene, shapes, request);
      result.energy += energy.energy;
      if (energy.energy > largest) {
        largest = energy.energy;
        result.severity_time = energy.severity_time;
      }
      result.terms.push_back({pair, std::move(energy)});
    }
  return result;
}

EnergyObjective resolution_objective(const scene::Reconfigurable& scene, int transition, Pair pair,
                                     const std::vector<Window>& windows, const std::vector<int>& movable, double reach,
                                     double proximity_reach) {
  EnergyObjective objective{transition, {{pair, windows}}, proximity_reach};
  std::set<Pair> listed{pair};
  const int n = static_cast<int>(scene.parts.size());
  std::vector<Eigen::AlignedBox3d> boxes(n);
  for (int p = 0; p < n; ++p) boxes[p] = swept_box(scene, transition, p, windows);
  for (int m : movable) {
    Eigen::AlignedBox3d reachable = boxes[m];
    reachable.extend(boxes[m].min() - Eigen::Vector3d::Constant(reach));
    reachable.extend(boxes[m].max() + Eigen::Vector3d::Constant(reach));
    for (int other = 0; other < n; ++other) {
      const Pair key{std::min(m, other), std::max(m, other)};
      if (other == m || listed.count(key) || !reachable.intersects(boxes[other])) continue;
      listed.insert(key);
      objective.pairs.push_back({key, windows});
    }
  }
  return objective;
}

}  // namespace reconfig::resolve::detail
