#pragma once
/// @file
/// The reconfigurable: parts, states (graph nodes) and transitions (graph edges).

#include <optional>
#include <string>
#include <vector>

#include "reconfig/geometry/mesh.h"
#include "reconfig/scene/collision_settings.h"
#include "reconfig/scene/part.h"
#include "reconfig/scene/saved_view.h"
#include "reconfig/scene/state.h"
#include "reconfig/scene/transition.h"

namespace reconfig::scene {

/// A whole design. Plain data plus look-ups; edits go through `Command`s (command.h) so they
/// can be undone and report what they dirtied.
struct Reconfigurable {
  std::string units = "m";
  std::vector<Part> parts;
  std::vector<State> states;
  std::vector<Transition> transitions;
  /// How its collisions are detected, as saved with it.
  CollisionSettings collision;
  /// The camera it was last saved with, if any (not an edit: saving sets it, undo ignores it).
  std::optional<SavedView> view;
  /// It stands on a ground (a floor under its lowest point): views of its collisions are then
  /// chosen from above, never from below (render/best_view.h). False for a floating design.
  bool ground = true;

  /// Index of the part / state / transition with that name, or -1.
  int find_part(const std::string& name) const;
  int find_state(const std::string& name) const;
  int find_transition(const std::string& name) const;

  /// The keyframed track of part `part` in transition `transition`, or null when the part
  /// holds still there or moves by screw poses.
  const KeyframedTrack* keyframed_track(int transition, int part) const;
  /// Pose of part `part` at time t ∈ [0, 1] of transition `transition` (eq. 9 parameters).
  motion::Pose pose_at(int transition, int part, double t) const;

  /// Rest mesh of `part` moved to its pose at time t: #V×3 positions, same faces.
  Eigen::MatrixX3d posed_vertices(int transition, int part, double t) const;

  /// Rest mesh of `part` moved to its pose in state `state`.
  Eigen::MatrixX3d posed_vertices_in_state(int state, int part) const;
};

}  // namespace reconfig::scene
