#include "reconfig/resolve/hints.h"

#include "reconfig/resolve/interval_energy.h"

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
    const IntervalEnergy energy =
        interval_energy(scene, shapes, request.transition, ci, request.time_margin, request.part);
    result.energy += energy.energy;
    if (!energy.pairs.empty() && energy.energy > largest) {
      largest = energy.energy;
      result.severity_time = energy.severity_time;
    }
    for (const auto& [pair, pair_energy] : energy.pairs)
      gradient += energy_gradient(scene, request.transition, request.part, dofs, pair_energy, true);
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
