#pragma once
/// @file
/// Undoable edits of a design's transitions (the edges of its state graph): add one with a
/// default choreography, rename, delete, reverse, duplicate.
///
/// Bad input (an empty or taken name, an unknown state or transition) is refused in `apply`
/// with an InputError naming it, leaving the design untouched.

#include <memory>
#include <string>

#include "reconfig/scene/command.h"

namespace reconfig::scene {

/// How a new transition moves the parts whose poses differ in its two states.
enum class Choreography {
  kStraight,  ///< translation on the straight line at constant speed (Bézier handles at the
              ///< thirds), rotation by slerp: a keyframed track
  kScrew,     ///< one screw motion from pose to pose (Rossignac & Kim): a screw-poses track
};

/// The track that moves a part from pose `from` to pose `to` over [0, 1] as `choreography` says.
Track default_track(const motion::Pose& from, const motion::Pose& to, Choreography choreography);

/// Appends a transition `name` from state `from` to state `to` (which may be the same state)
/// in which every part whose poses there differ moves by `default_track`; the others hold
/// still. Its dirty set names it in `added_transitions`: the collision service detects it alone.
std::unique_ptr<Command> add_transition(std::string name, std::string from, std::string to,
                                        Choreography choreography = Choreography::kStraight);

std::unique_ptr<Command> rename_transition(std::string transition, std::string new_name);

std::unique_ptr<Command> delete_transition(std::string transition);

/// Swaps the transition's ends and plays its tracks backwards (time t becomes 1 − t, each
/// translation key's handles swap): the same motion in the other direction. A transition a
/// linkage drives is refused (swap the drive's motor angles instead).
std::unique_ptr<Command> reverse_transition(std::string transition);

/// Appends a copy of the transition named `new_name`: an alternative choreography between the
/// same states, to edit on its own (as the bench's `unfold` and `unfold_lifted`); detected
/// alone, as an added one.
std::unique_ptr<Command> duplicate_transition(std::string transition, std::string new_name);

}  // namespace reconfig::scene
