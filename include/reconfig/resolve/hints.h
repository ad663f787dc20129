#pragma once
/// @file
/// Resolution hints (reconfigurables §6.5, Fig. 16): for a selected part and collision
/// interval, the energy's descent direction projected on each of the part's UI elements.

#include <Eigen/Core>

#include <vector>

#include "reconfig/collision/collision_interval.h"
#include "reconfig/resolve/key_dofs.h"
#include "reconfig/resolve/pair_energy.h"
#include "reconfig/resolve/shape_cache.h"
#include "reconfig/scene/reconfigurable.h"

namespace reconfig::resolve {

/// How one UI element should move.
struct Hint {
  KeyDof dof;
  /// ∂E/∂(the element's coordinates): a 3-vector in scene units for points and handles, an
  /// axis-angle 3-vector (radians) for a rotation, a number for a time.
  Eigen::VectorXd gradient;
  /// The unit descent direction −gradient/|gradient| (zero when the gradient is).
  Eigen::VectorXd direction;
  /// dE/ds along `direction` (= −|gradient|): how fast the energy falls per unit moved.
  double slope = 0;
};

struct HintRequest {
  int transition = 0;
  int part = 0;
  /// The collision intervals to resolve: each pair (part, other part of an interval)
  /// contributes its energy over the interval's time extent; intervals without `part` add none.
  std::vector<collision::CollisionInterval> intervals = {};
  DofSelection dofs = {};
  /// Each interval's extent is widened by this much on both sides (clipped to [0, 1]): see
  /// `interval_energy`.
  double time_margin = 0.01;
};

struct HintResult {
  double energy = 0;  ///< the summed energy of the intervals' pairs with `part`
  double severity_time = 0;  ///< of the most energetic pair
  std::vector<Hint> hints;   ///< one per degree of freedom, in `key_dofs` order
};

/// The hints for `request.part`. A part without keyframed degrees of freedom gets none (its
/// energy is still reported).
HintResult compute_hints(const scene::Reconfigurable& scene, ShapeCache& shapes, const HintRequest& request);

/// ∂E/∂(coordinates of `dofs` of `part`) from the samples of `energy`, a `pair_energy` of a
/// pair that includes `part` (`part_is_a`: as its part a): the chain rule of eq. 3,
/// Σ_samples weight · J(t)ᵀ G_t with J the part's `twist_jacobian`.
Eigen::VectorXd energy_gradient(const scene::Reconfigurable& scene, int transition, int part,
                                const std::vector<KeyDof>& dofs, const PairEnergy& energy, bool part_is_a);

}  // namespace reconfig::resolve
