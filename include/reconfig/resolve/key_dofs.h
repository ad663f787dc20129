#pragma once
/// @file
/// The designer's degrees of freedom of a keyframed part in a transition — each inner key's
/// point, its Bézier handles, each inner rotation key, each inner key's time — and how they
/// move the part (the chain rule of the reconfigurables appendix).

#include <Eigen/Core>

#include <string>
#include <vector>

#include "reconfig/scene/edits.h"
#include "reconfig/scene/reconfigurable.h"

namespace reconfig::resolve {

enum class DofKind {
  kTranslation,  ///< a translation key's point, its handles moving with it (as a drag does); 3
  kHandleIn,     ///< a translation key's in handle u_j; 3
  kHandleOut,    ///< a translation key's out handle w_j; 3
  kRotation,     ///< a rotation key, turned by exp(δ) in the world frame (δ axis-angle); 3
  kTime,         ///< a key's time; 1
};

/// One degree of freedom: a key of one of the part's key lists.
struct KeyDof {
  DofKind kind = DofKind::kTranslation;
  scene::KeyKind track = scene::KeyKind::kTranslation;  ///< the key list `key` indexes
  int key = 0;
  int size() const { return kind == DofKind::kTime ? 1 : 3; }
};

/// Which kinds to list.
struct DofSelection {
  bool handles = true;
  /// The first key's out handle and the last key's in handle: how the part leaves and
  /// reaches its states (parts stowed in tight places can only leave one way).
  bool end_handles = true;
  bool rotations = true;
  bool times = true;
  /// The first and last keys' points and rotations: the part's poses in the transition's
  /// states. Moving one moves the part in that state, so every transition through the state
  /// changes (`displace_keys`). Their times never move.
  bool end_keys = false;
};

/// The degrees of freedom of part `part` in transition `transition`, in key order: the points,
/// rotations and times of inner keys, and the handles that shape the motion (the out handle of
/// the first translation key and the in handle of the last included: how the part leaves and
/// reaches its states). The end keys' points and rotations are the states' poses and are
/// listed only with `selection.end_keys`. A part without a keyframed track (still, screw poses, or driven by a linkage) has
/// none.
std::vector<KeyDof> key_dofs(const scene::Reconfigurable& scene, int transition, int part,
                             const DofSelection& selection = {});

/// Total number of coordinates of `dofs`.
int dof_coordinates(const std::vector<KeyDof>& dofs);

/// The rigid velocity of the part at time t per unit change of each coordinate of `dofs`:
/// column k is the twist (v; ω) — u(y) = v + ω × y about the world origin — that coordinate k
/// gives the part. 6 × dof_coordinates(dofs).
Eigen::Matrix<double, 6, Eigen::Dynamic> twist_jacobian(const scene::Reconfigurable& scene, int transition, int part,
                                                        const std::vector<KeyDof>& dofs, double t);

/// Moves the keys of `dofs` by `step` (dof_coordinates(dofs) numbers, in their order): points
/// with their handles, handles, rotations by exp(δ) in the world frame, times. An end key's
/// point or rotation moves the part's pose in that state (`scene::set_state_pose`): the end
/// keys of every transition through the state follow, this one's included.
/// @throws InputError if a time step would put keys out of order
void displace_keys(scene::Reconfigurable& scene, int transition, int part, const std::vector<KeyDof>& dofs,
                   const Eigen::VectorXd& step);

/// "translation", "handle_in", "handle_out", "rotation" or "time".
std::string dof_kind_name(DofKind kind);

}  // namespace reconfig::resolve
