#include "reconfig/resolve/hints.h"

#include <algorithm>

namespace reconfig::resolve {

Eigen::VectorXd energy_gradient(const scene::Reconfigurable& scene, int transition, int part,
                                const std::vector<KeyDof>& dofs, const PairEnergy& energy, bool part_is_a) {
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero(dof_coordinates(dofs));
  if (dofs.empty()) return gradient;
  for (const EnergySample& sample : energy.samples) {
    if (sample.density() == 0) continue;  // nothing crosses: no gradient there
    const Eigen::Matrix<double, 6, 1> g = (part_is_a ? sample.gradient : -sample.gradient).stacked();
    gradient += sample.weight * (twist_jacobian(scene, transition, part, dofs, sample.time).transpose() * g);
  }
  return gradient;
}

HintResult compute_hints(const scene::Reconfigurable& scene, ShapeCache& shapes, const HintRequest& request) {
  const std::vector<KeyDof> dofs = key_dofs(scene, request.transition, request.part, request.dofs);
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero(dof_coordinates(dofs));
  HintResult result;
  double largest = -1;
  for (const collision::CollisionInterval& ci : request.intervals) {
    if (std::find(ci.parts.begin(), ci.parts.end(), request.part) == ci.parts.end()) continue;
    for (int other : ci.parts) {
      if (other == request.part) continue;
      PairEnergyRequest pair;
      pair.transition = request.transition;
      pair.part_a = request.part;
      pair.part_b = other;
      pair.t0 = std::max(0.0, ci.t0 - request.time_margin);
      pair.t1 = std::min(1.0, ci.t1 + request.time_margin);
      const PairEnergy energy = pair_energy(scene, shapes, pair);
      result.energy += energy.energy;
      if (energy.energy > largest) {
        largest = energy.energy;
        result.severity_time = energy.severity_time;
      }
      gradient += energy_gradient(scene, request.transition, request.part, dofs, energy, true);
    }
  }
  int column = 0;
  for (const KeyDof& dof : dofs) {
    Hint hint;
    hint.dof = dof;
    hint.gradient = gradient.segment(column, dof.size());
    const double norm = hint.gradient.norm();
    hint.direction = norm > 0 ? Eigen::VectorXd(-hint.gradient / norm) : Eigen::VectorXd::Zero(dof.size());
    hint.slope = -norm;
    result.hints.push_back(std::move(hint));
    column += dof.size();
  }
  return result;
}

}  // namespace reconfig::resolve
