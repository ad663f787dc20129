#include "reconfig/resolve/auto_resolve.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <utility>

#include "reconfig/collision/detect_collisions.h"
#include "reconfig/common/input_error.h"
#include "reconfig/geometry/bounding_box.h"
#include "reconfig/motion/key_error.h"
#include "reconfig/resolve/key_dofs.h"
#include "reconfig/resolve/proximity.h"
#include "reconfig/scene/edits.h"
#include "resolve/detail/descent_space.h"
#include "resolve/detail/energy_objective.h"
#include "resolve/detail/line_search.h"

namespace reconfig::resolve {
namespace {

using detail::EnergyObjective;
using detail::ObjectiveEnergy;
using detail::Pair;
using detail::Window;

std::vector<collision::CollisionInterval> detect(const scene::Reconfigurable& scene, const AutoResolveRequest& request,
                                                 int transition) {
  collision::CollisionRequest detection;
  detection.detector = request.detector;
  detection.transitions = {transition};
  const collision::CollisionResult result = collision::detect_collisions(scene, detection);
  return result.transitions.empty() ? std::vector<collision::CollisionInterval>{} : result.transitions[0].intervals;
}

std::vector<collision::CollisionInterval> detect(const scene::Reconfigurable& scene, const AutoResolveRequest& request) {
  return detect(scene, request, request.transition);
}

/// The states in which some part's pose differs between two versions of a design, with
/// "part in state" for each such part.
std::map<std::string, std::vector<std::string>> moved_states(const scene::Reconfigurable& before,
                                                             const scene::Reconfigurable& after) {
  std::map<std::string, std::vector<std::string>> moved;
  for (std::size_t s = 0; s < after.states.size(); ++s)
    for (const scene::Part& part : after.parts) {
      const motion::Pose a = before.states[s].pose_of(part.name), b = after.states[s].pose_of(part.name);
      if (a != b)
        moved[after.states[s].name].push_back(fmt::format("{} in {}", part.name, after.states[s].name));
    }
  return moved;
}

/// The transitions other than the one being resolved that pass through a moved state.
std::vector<int> transitions_through(const scene::Reconfigurable& scene,
                                     const std::map<std::string, std::vector<std::string>>& states, int except) {
  std::vector<int> through;
  for (int t = 0; t < static_cast<int>(scene.transitions.size()); ++t)
    if (t != except && (states.count(scene.transitions[t].from) || states.count(scene.transitions[t].to)))
      through.push_back(t);
  return through;
}

/// The first transition through one of the `moved` states that has more collision intervals
/// after a round than before it, as a reason to undo the round; empty when there is none.
std::string worsened_elsewhere(const scene::Reconfigurable& before, const scene::Reconfigurable& after,
                               const std::map<std::string, std::vector<std::string>>& moved,
                               const AutoResolveRequest& request) {
  for (int t : transitions_through(after, moved, request.transition)) {
    const std::size_t was = detect(before, request, t).size(), now = detect(after, request, t).size();
    if (now > was)
      return fmt::format("moving the states would give {} {} collision interval(s) instead of {}",
                         after.transitions[t].name, now, was);
  }
  return "";
}

/// The pairs of parts that collide in an interval: those of its witness triangle pairs (an
/// interval may merge the contacts of several pairs), or every pair of its parts when it has
/// none (containment).
std::set<Pair> colliding_pairs(const collision::CollisionInterval& ci) {
  std::set<Pair> pairs;
  for (const auto& t : ci.triangles) pairs.insert({std::min(t[0], t[2]), std::max(t[0], t[2])});
  if (pairs.empty())
    for (std::size_t i = 0; i < ci.parts.size(); ++i)
      for (std::size_t j = i + 1; j < ci.parts.size(); ++j) pairs.insert({ci.parts[i], ci.parts[j]});
  return pairs;
}

/// The time windows of each pair of parts that collide: their intervals, widened so that the
/// energy still sees the collision as the keys move it in time, and merged where they overlap.
std::map<Pair, std::vector<Window>> pair_windows(const std::vector<collision::CollisionInterval>& intervals) {
  std::map<Pair, std::vector<Window>> windows;
  for (const auto& ci : intervals) {
    const double pad = std::max(0.02, 0.5 * ci.duration());
    for (const Pair& pair : colliding_pairs(ci))
      windows[pair].push_back({std::max(0.0, ci.t0 - pad), std::min(1.0, ci.t1 + pad)});
  }
  for (auto& [pair, list] : windows) {
    std::sort(list.begin(), list.end());
    std::vector<Window> merged;
    for (const Window& w : list) {
      if (!merged.empty() && w.first <= merged.back().second) merged.back().second = std::max(merged.back().second, w.second);
      else merged.push_back(w);
    }
    list = std::move(merged);
  }
  return windows;
}

/// Inserts a translation key (and a rotation key if the part has a rotation track) at the
/// severity time `t` unless the part has an inner key near it (within an eighth of the
/// window): a key elsewhere in the window moves the part at t only a little.
std::vector<std::string> ensure_inner_keys(scene::Reconfigurable& scene, int transition, int part, Window window,
                                           double t) {
  std::vector<std::string> inserted;
  if (t < window.first || t > window.second) return inserted;
  const double near = (window.second - window.first) / 8;
  const auto& track = std::get<scene::KeyframedTrack>(scene.transitions[transition].tracks.at(scene.parts[part].name));
  const auto has_key_near = [&](const auto& keys) {
    for (std::size_t j = 1; j + 1 < keys.size(); ++j)
      if (std::abs(keys[j].time - t) <= near) return true;
    return false;
  };
  const bool need_translation = !has_key_near(track.translation);
  const bool need_rotation = track.rotation.size() >= 2 && !has_key_near(track.rotation);
  const auto insert = [&](scene::KeyKind kind, const char* what) {
    try {
      scene::insert_key(scene.transitions[transition].name, scene.parts[part].name, kind, t)->apply(scene);
      inserted.push_back(fmt::format("{} {} {:.4f}", scene.parts[part].name, what, t));
    } catch (const InputError&) {
      // t at an end, or a key already there: the existing keys are the degrees of freedom.
    }
  };
  if (need_translation) insert(scene::KeyKind::kTranslation, "translation");
  if (need_rotation) insert(scene::KeyKind::kRotation, "rotation");
  return inserted;
}

/// Size of the pair: the larger of the two parts' box diagonals.
double pair_size(const scene::Reconfigurable& scene, Pair pair) {
  const auto diagonal = [&](int part) { return geometry::bounding_box(scene.parts[part].mesh.V).diagonal().norm(); };
  return std::max(diagonal(pair.first), diagonal(pair.second));
}

/// Asks the caller's progress callback, at every energy evaluation, whether to go on.
struct Cancellation {
  const ProgressCallback& progress;
  double fraction = 0;  ///< reported: the round's share of the rounds
  bool cancelled = false;
  bool requested() {
    if (!cancelled && !report_progress(progress, fraction)) cancelled = true;
    return cancelled;
  }
};

/// The objective at z, or +infinity where z makes no valid design (or once cancelled).
double energy_at(const detail::DescentSpace& space, const Eigen::VectorXd& z, const EnergyObjective& objective,
                 ShapeCache& shapes, Cancellation& cancel) {
  if (cancel.requested()) return std::numeric_limits<double>::infinity();
  try {
    return detail::evaluate(objective, space.at(z), shapes).energy;
  } catch (const InputError&) {
    return std::numeric_limits<double>::infinity();
  } catch (const motion::KeyError&) {
    return std::numeric_limits<double>::infinity();
  }
}

struct RoundOutcome {
  scene::Reconfigurable scene;
  ResolveRound round;
};

/// Holds (sets in `held`) the coordinates of the descent −g along which a small step already
/// raises the objective above e0: a part touching another (a drawer in its runners) has no
/// contour yet, so the gradient cannot see that the smallest move into it makes one appear at
/// full length (the contour energy jumps there). Each coordinate not yet held is probed at every
/// length of `probes`.
void hold_rising_coordinates(const Eigen::VectorXd& g, double e0, std::initializer_list<double> probes,
                             const std::function<double(const Eigen::VectorXd&)>& energy, std::vector<bool>& held) {
  for (int k = 0; k < g.size(); ++k)
    for (double probe : probes) {
      if (held[k] || g[k] == 0) break;
      Eigen::VectorXd z = Eigen::VectorXd::Zero(g.size());
      z[k] = g[k] < 0 ? probe : -probe;
      if (energy(z) > e0) held[k] = true;
    }
}

/// The descent direction −g/|g| without the held coordinates, normalized (zero when all are).
Eigen::VectorXd feasible_direction(const Eigen::VectorXd& g, const std::vector<bool>& held) {
  Eigen::VectorXd d = -g / g.norm();
  for (int k = 0; k < d.size(); ++k)
    if (held[k]) d[k] = 0;
  const double norm = d.norm();
  return norm > 0 ? Eigen::VectorXd(d / norm) : d;
}

/// Gradient descent of `objective` over the keys of `movable` from `scene`.
scene::Reconfigurable descend_with(scene::Reconfigurable scene, ShapeCache& shapes, const AutoResolveRequest& request,
                                   const EnergyObjective& objective, const std::vector<int>& movable, double size,
                                   Cancellation& cancel, int& steps) {
  const int tr = request.transition;
  const double clearance = std::max(4 * request.detector.tolerance, 0.01 * size);
  const DofSelection selection{
      .handles = true, .end_handles = false, .rotations = true, .times = request.move_times, .end_keys = request.move_states};
  ObjectiveEnergy energy = detail::evaluate(objective, scene, shapes);
  steps = 0;
  for (int step = 0; step < request.max_steps && energy.energy > 0 && !cancel.requested(); ++step) {
    const detail::DescentSpace space(scene, tr, movable, selection, size);
    const Eigen::VectorXd g = space.gradient(scene, energy);
    if (g.norm() == 0 || !std::isfinite(g.norm())) break;
    const auto at = [&](const Eigen::VectorXd& z) { return energy_at(space, z, objective, shapes, cancel); };
    const auto search = [&](const Eigen::VectorXd& d) {
      return d.norm() > 0 ? detail::line_search([&](double a) { return at(a * d); }, energy.energy, size, clearance)
                          : 0.0;
    };
    std::vector<bool> held(g.size(), false);
    hold_rising_coordinates(g, energy.energy, {1e-5 * size}, at, held);
    Eigen::VectorXd d = feasible_direction(g, held);
    double alpha = search(d);
    if (alpha == 0) {  // a contact may lie a little farther than the probe looked: probe farther
      hold_rising_coordinates(g, energy.energy, {1e-4 * size, 1e-3 * size}, at, held);
      d = feasible_direction(g, held);
      alpha = search(d);
    }
    if (alpha == 0) break;
    scene = space.at(alpha * d);
    energy = detail::evaluate(objective, scene, shapes);
    steps = step + 1;
  }
  return scene;
}

/// One round on one pair: descent over the keys of both parts, and of each alone when both
/// move (moving one part may be what the design allows: a drawer in its runners, a door on
/// its hinge), keeping the result whose objective — the pair and what its moving parts may
/// run into — is lowest.
RoundOutcome descend(const scene::Reconfigurable& original, ShapeCache& shapes, const AutoResolveRequest& request,
                     Pair pair, const std::vector<Window>& windows, ResolveRound round, Cancellation& cancel) {
  const int tr = request.transition;
  scene::Reconfigurable scene = original;
  std::vector<int> movable;
  for (int part : {pair.first, pair.second})
    if (scene.keyframed_track(tr, part)) movable.push_back(part);
  const double proximity = proximity_reach(request.detector);
  const EnergyObjective own{tr, {{pair, windows}}, proximity};
  const ObjectiveEnergy before = detail::evaluate(own, scene, shapes);
  round.energy_before = round.energy_after = before.energy;
  if (movable.empty() || before.energy == 0) return {std::move(scene), round};
  for (int part : movable)
    for (const Window& w : windows)
      for (std::string& key : ensure_inner_keys(scene, tr, part, w, before.severity_time))
        round.inserted_keys.push_back(std::move(key));
  const double size = pair_size(scene, pair);
  const EnergyObjective objective = detail::resolution_objective(scene, tr, pair, windows, movable, size, proximity);
  std::vector<std::vector<int>> choices{movable};
  if (movable.size() == 2) choices.insert(choices.end(), {{movable[0]}, {movable[1]}});
  std::optional<scene::Reconfigurable> best;
  double best_energy = std::numeric_limits<double>::infinity();
  for (const std::vector<int>& parts : choices) {
    int steps = 0;
    scene::Reconfigurable moved = descend_with(scene, shapes, request, objective, parts, size, cancel, steps);
    const double e = detail::evaluate(objective, moved, shapes).energy;
    if (e < best_energy) {
      best_energy = e;
      best = std::move(moved);
      round.steps = steps;
    }
    if (e == 0 || cancel.cancelled) break;
  }
  const double after = best ? detail::evaluate(own, *best, shapes).energy : before.energy;
  if (cancel.cancelled || !(after < before.energy)) {  // nothing gained: not even the inserted keys stay
    round.inserted_keys.clear();
    round.steps = 0;
    return {original, round};
  }
  round.energy_after = after;
  return {std::move(*best), round};
}

/// With states free to move: records which parts moved in which state, and undoes the round
/// when that gave another transition through those states more collision intervals.
void undo_if_worse_elsewhere(const scene::Reconfigurable& before, const AutoResolveRequest& request,
                             RoundOutcome& outcome) {
  const auto moved = moved_states(before, outcome.scene);
  for (const auto& [state, parts] : moved)
    outcome.round.moved_states.insert(outcome.round.moved_states.end(), parts.begin(), parts.end());
  if (moved.empty()) return;
  outcome.round.undone_because = worsened_elsewhere(before, outcome.scene, moved, request);
  if (outcome.round.undone_because.empty()) return;
  outcome.scene = before;
  outcome.round.energy_after = outcome.round.energy_before;
  outcome.round.inserted_keys.clear();
  outcome.round.moved_states.clear();
  outcome.round.steps = 0;
}

}  // namespace

AutoResolveResult auto_resolve(const scene::Reconfigurable& input, const AutoResolveRequest& request) {
  AutoResolveResult result;
  result.scene = input;
  ShapeCache shapes;
  std::set<Pair> stuck;  // pairs whose last round lowered nothing
  for (int r = 0; r < request.max_rounds; ++r) {
    if (!report_progress(request.progress, static_cast<double>(r) / request.max_rounds)) {
      result.cancelled = true;
      result.stopped_because = "cancelled";
      break;
    }
    const std::vector<collision::CollisionInterval> intervals = detect(result.scene, request);
    result.intervals_left = static_cast<int>(intervals.size());
    if (intervals.empty()) {
      result.collision_free = true;
      result.stopped_because = "the transition is collision-free";
      break;
    }
    // The pair that contributes most energy, among those not known to be stuck.
    const auto windows = pair_windows(intervals);
    Pair chosen{-1, -1};
    double largest = 0;
    for (const auto& [pair, list] : windows) {
      if (stuck.count(pair)) continue;
      const double e =
          detail::evaluate({request.transition, {{pair, list}}, proximity_reach(request.detector)}, result.scene, shapes)
              .energy;
      if (e > largest) largest = e, chosen = pair;
    }
    if (chosen.first < 0) {
      result.stopped_because = "no step lowers the energy of the pairs that still collide (parts that only touch, or "
                               "that the keys cannot move apart, have none to lower)";
      break;
    }
    ResolveRound round;
    round.round = r;
    round.pair = {chosen.first, chosen.second};
    round.intervals_before = static_cast<int>(intervals.size());
    Cancellation cancel{request.progress, static_cast<double>(r) / request.max_rounds};
    RoundOutcome outcome = descend(result.scene, shapes, request, chosen, windows.at(chosen), round, cancel);
    if (cancel.cancelled) {
      result.cancelled = true;
      result.stopped_because = "cancelled";
      break;
    }
    if (request.move_states) undo_if_worse_elsewhere(result.scene, request, outcome);
    result.scene = std::move(outcome.scene);
    if (!(outcome.round.energy_after < outcome.round.energy_before)) stuck.insert(chosen);
    else stuck.clear();  // the design changed: other pairs may move again
    if (request.on_round) request.on_round(outcome.round);
    result.rounds.push_back(std::move(outcome.round));
  }
  if (result.stopped_because.empty()) {
    const auto intervals = detect(result.scene, request);
    result.intervals_left = static_cast<int>(intervals.size());
    result.collision_free = intervals.empty();
    result.stopped_because = result.collision_free ? "the transition is collision-free"
                                                   : fmt::format("stopped after {} rounds", request.max_rounds);
  }
  for (int t : transitions_through(result.scene, moved_states(input, result.scene), request.transition))
    result.rechecked.emplace_back(result.scene.transitions[t].name, static_cast<int>(detect(result.scene, request, t).size()));
  return result;
}

}  // namespace reconfig::resolve
