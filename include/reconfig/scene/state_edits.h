#pragma once
/// @file
/// Undoable edits of a design's states (the nodes of its state graph): add, rename, delete.
/// (Posing a part in a state is `set_state_pose`, edits.h.)
///
/// Bad input (an empty or taken name, an unknown state) is refused in `apply` with an
/// InputError naming the state, leaving the design untouched.

#include <map>
#include <memory>
#include <string>

#include "reconfig/motion/pose.h"
#include "reconfig/scene/command.h"

namespace reconfig::scene {

/// The pose of every part at time t of transition `transition`, or in state `state` when
/// `transition` is −1: what a new state copies from what the editor shows.
std::map<std::string, motion::Pose> current_poses(const Reconfigurable& scene, int transition, int state, double t);

/// Appends a state named `name` with `poses` (by part name; a part not listed rests at the
/// identity pose). No transition uses it yet, so nothing is dirtied.
std::unique_ptr<Command> add_state(std::string name, std::map<std::string, motion::Pose> poses);

/// Renames a state, and the ends of the transitions that use it.
std::unique_ptr<Command> rename_state(std::string state, std::string new_name);

/// Removes a state. While transitions start or end there the removal is refused with their
/// names, unless `with_transitions`, which removes them too. A design keeps at least one state
/// (what the editor shows when no transition is open): deleting the last is refused.
std::unique_ptr<Command> delete_state(std::string state, bool with_transitions = false);

}  // namespace reconfig::scene
