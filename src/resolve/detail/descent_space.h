#pragma once
/// @file
/// The space automatic resolution descends in: the keys of the parts it may move, as one vector.

#include <Eigen/Core>

#include <vector>

#include "reconfig/resolve/key_dofs.h"
#include "reconfig/scene/reconfigurable.h"
#include "resolve/detail/energy_objective.h"

namespace reconfig::resolve::detail {

/// A point z of the descent is a displacement of every degree of freedom of the movable parts,
/// in length units: rotations scaled by the part's radius (a turn by z/r moves its farthest
/// point by about z), key times by the design's `length` (when times may move at all).
class DescentSpace {
 public:
  DescentSpace(const scene::Reconfigurable& base, int transition, std::vector<int> parts, const DofSelection& selection,
               double length);
  int size() const { return static_cast<int>(scale_.size()); }
  /// The base design displaced by z (z = 0 is the base). @throws InputError where z would put
  /// key times out of order
  scene::Reconfigurable at(const Eigen::VectorXd& z) const;
  /// ∂E/∂z at `scene` (= at(z)) from the objective's samples there.
  Eigen::VectorXd gradient(const scene::Reconfigurable& scene, const ObjectiveEnergy& energy) const;

 private:
  scene::Reconfigurable base_;  ///< a copy: the descent replaces the design it started from
  int transition_;
  std::vector<int> parts_;
  std::vector<std::vector<KeyDof>> dofs_;
  std::vector<double> scale_;
};

}  // namespace reconfig::resolve::detail
