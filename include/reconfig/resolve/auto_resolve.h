#pragma once
/// @file
/// Automatic resolution (reconfigurables §6.6): gradient descent on the intersection energy
/// with a golden-section line search, greedily over pairs of parts, until a transition is
/// collision-free or no step lowers the energy.

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "reconfig/collision/spacetime_detector.h"
#include "reconfig/common/progress.h"
#include "reconfig/scene/reconfigurable.h"

namespace reconfig::resolve {

/// One greedy round: the pair with the largest energy, and what the descent did to it.
struct ResolveRound {
  int round = 0;
  std::vector<int> pair;          ///< the two parts
  double energy_before = 0;       ///< of the pair, over its intervals
  double energy_after = 0;
  int steps = 0;                  ///< descent steps taken
  int intervals_before = 0;       ///< of the whole transition, detected at the round's start
  std::vector<std::string> inserted_keys;  ///< keys inserted at the severity time ("part translation 0.42")
  /// With `move_states`: the parts moved in a state, as "part in state".
  std::vector<std::string> moved_states;
  /// A round undone because its state moves gave another transition more intervals: which.
  std::string undone_because;
};

struct AutoResolveRequest {
  int transition = 0;
  collision::DetectorOptions detector = {};  ///< how collisions are detected between rounds
  int max_rounds = 30;
  int max_steps = 12;  ///< descent steps per round
  /// Key times stay put unless this is set (moving times changes the choreography's timing).
  bool move_times = false;
  /// The end keys may move too: the part's poses in the transition's states, and with them
  /// every transition through those states. A round whose state moves give another of those
  /// transitions more collision intervals is undone.
  bool move_states = false;
  ProgressCallback progress = nullptr;  ///< fraction of max_rounds; false cancels
  std::function<void(const ResolveRound&)> on_round = nullptr;  ///< after each round
};

struct AutoResolveResult {
  scene::Reconfigurable scene;  ///< the design with its keys moved (meshes untouched; states only with move_states)
  bool collision_free = false;  ///< by the detector, after the last round
  bool cancelled = false;
  int intervals_left = 0;
  std::vector<ResolveRound> rounds;
  std::string stopped_because;  ///< one line for people
  /// With `move_states`: the other transitions through the states that moved, and how many
  /// collision intervals each has now (re-checked after the last round).
  std::vector<std::pair<std::string, int>> rechecked;
};

/// Resolves the collisions of one transition by moving its inner keys with their handles. The
/// end keys are the states' poses and stay fixed unless `move_states`, and so do their handles (how a part leaves
/// and reaches a state: a stowed part can often leave only one way). A part of a pair with
/// no inner key near the severity time (within an eighth of the pair's time window) gets one
/// inserted there first (the motion is unchanged by the insertion). Each round descends on the
/// pair's energy plus that of its moving parts against every part they may reach, so that a
/// move does not trade one collision for another. Parts without keyframed tracks (screw poses,
/// linkage drives, still parts) are not moved.
AutoResolveResult auto_resolve(const scene::Reconfigurable& scene, const AutoResolveRequest& request);

}  // namespace reconfig::resolve
