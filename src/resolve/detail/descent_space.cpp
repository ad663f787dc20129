#include "resolve/detail/descent_space.h"

#include <algorithm>

#include "reconfig/resolve/hints.h"

namespace reconfig::resolve::detail {

DescentSpace::DescentSpace(const scene::Reconfigurable& base, int transition, std::vector<int> parts,
                           const DofSelection& selection, double length)
    : base_(base), transition_(transition), parts_(std::move(parts)) {
  for (int part : parts_) {
    dofs_.push_back(key_dofs(base, transition, part, selection));
    const scene::Part& p = base.parts[part];
    double radius = 0;
    for (int v = 0; v < p.mesh.vertex_count(); ++v) radius = std::max(radius, (p.mesh.V.row(v).transpose() - p.center).norm());
    for (const KeyDof& dof : dofs_.back())
      for (int c = 0; c < dof.size(); ++c)
        scale_.push_back(dof.kind == DofKind::kRotation ? std::max(radius, 1e-9) : dof.kind == DofKind::kTime ? length : 1.0);
  }
}

scene::Reconfigurable DescentSpace::at(const Eigen::VectorXd& z) const {
  scene::Reconfigurable moved = base_;
  int offset = 0;
  for (std::size_t i = 0; i < parts_.size(); ++i) {
    const int n = dof_coordinates(dofs_[i]);
    Eigen::VectorXd step(n);
    for (int k = 0; k < n; ++k) step[k] = z[offset + k] / scale_[offset + k];
    displace_keys(moved, transition_, parts_[i], dofs_[i], step);
    offset += n;
  }
  return moved;
}

Eigen::VectorXd DescentSpace::gradient(const scene::Reconfigurable& scene, const ObjectiveEnergy& energy) const {
  Eigen::VectorXd g(size());
  int offset = 0;
  for (std::size_t i = 0; i < parts_.size(); ++i) {
    const int part = parts_[i];
    const int n = dof_coordinates(dofs_[i]);
    Eigen::VectorXd gx = Eigen::VectorXd::Zero(n);
    for (const ObjectiveTerm& term : energy.terms)
      if (term.pair.first == part || term.pair.second == part)
        gx += energy_gradient(scene, transition_, part, dofs_[i], term.energy, term.pair.first == part);
    for (int k = 0; k < n; ++k) g[offset + k] = gx[k] / scale_[offset + k];
    offset += n;
  }
  return g;
}

}  // namespace reconfig::resolve::detail
