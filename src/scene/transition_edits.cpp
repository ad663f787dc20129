// Edits of the list of transitions: add (with a default choreography), rename, delete,
// reverse, duplicate.

#include "reconfig/scene/transition_edits.h"

#include <fmt/format.h>

#include <algorithm>

#include "reconfig/scene/validate_scene.h"
#include "scene/detail/list_edit.h"

namespace reconfig::scene {
namespace {

/// Every part with a track in transition `index`, over the whole transition.
DirtySet all_tracks_dirty(const Reconfigurable& scene, int index) {
  DirtySet dirty;
  for (const auto& [part, track] : scene.transitions[index].tracks)
    dirty.ranges.push_back({index, scene.find_part(part), 0.0, 1.0});
  return dirty;
}

/// The same motion played backwards: time t becomes 1 − t.
Track reversed(const Track& track) {
  if (const auto* screw = std::get_if<ScrewPosesTrack>(&track)) {
    ScrewPosesTrack out;
    for (auto key = screw->poses.rbegin(); key != screw->poses.rend(); ++key) out.poses.push_back({1.0 - key->time, key->pose});
    return out;
  }
  const auto& keyed = std::get<KeyframedTrack>(track);
  KeyframedTrack out;
  for (auto key = keyed.translation.rbegin(); key != keyed.translation.rend(); ++key)
    out.translation.push_back({1.0 - key->time, key->point, key->out, key->in});
  for (auto key = keyed.rotation.rbegin(); key != keyed.rotation.rend(); ++key)
    out.rotation.push_back({1.0 - key->time, key->rotation});
  return out;
}

}  // namespace

Track default_track(const motion::Pose& from, const motion::Pose& to, Choreography choreography) {
  if (choreography == Choreography::kScrew) return ScrewPosesTrack{{{0.0, from}, {1.0, to}}};
  const Eigen::Vector3d a = from.translation, b = to.translation, third = (b - a) / 3;
  KeyframedTrack track;
  track.translation = {{0.0, a, a, a + third}, {1.0, b, b - third, b}};
  track.rotation = {{0.0, from.rotation}, {1.0, to.rotation}};
  return track;
}

std::unique_ptr<Command> add_transition(std::string name, std::string from, std::string to, Choreography choreography) {
  std::string label = fmt::format("add transition {} from {} to {}", name, from, to);
  return detail::list_edit(std::move(label), [=](Reconfigurable& scene) {
    detail::check_new_name(scene, "transition", name);
    const State& a = scene.states[detail::state_index(scene, from)];
    const State& b = scene.states[detail::state_index(scene, to)];
    Transition transition;
    transition.name = name;
    transition.from = from;
    transition.to = to;
    for (const Part& part : scene.parts) {
      const motion::Pose start = a.pose_of(part.name), end = b.pose_of(part.name);
      if (!poses_match(start, end)) transition.tracks[part.name] = default_track(start, end, choreography);
    }
    scene.transitions.push_back(std::move(transition));
    return detail::transition_appended(scene);
  });
}

std::unique_ptr<Command> rename_transition(std::string transition, std::string new_name) {
  std::string label = fmt::format("rename transition {} to {}", transition, new_name);
  return detail::list_edit(std::move(label), [=](Reconfigurable& scene) {
    const int index = detail::transition_index(scene, transition);
    detail::check_new_name(scene, "transition", new_name);
    scene.transitions[index].name = new_name;
    return DirtySet{};  // the collision engine knows transitions by index
  });
}

std::unique_ptr<Command> delete_transition(std::string transition) {
  std::string label = fmt::format("delete transition {}", transition);
  return detail::list_edit(std::move(label), [=](Reconfigurable& scene) {
    scene.transitions.erase(scene.transitions.begin() + detail::transition_index(scene, transition));
    return detail::structure_changed();
  });
}

std::unique_ptr<Command> reverse_transition(std::string transition) {
  std::string label = fmt::format("reverse transition {}", transition);
  return detail::list_edit(std::move(label), [=](Reconfigurable& scene) {
    const int index = detail::transition_index(scene, transition);
    Transition& edited = scene.transitions[index];
    if (edited.linkage)
      detail::refuse(fmt::format("transition \"{}\" is driven by a linkage: swap its motor angles instead", transition));
    std::swap(edited.from, edited.to);
    for (auto& [part, track] : edited.tracks) track = reversed(track);
    return all_tracks_dirty(scene, index);
  });
}

std::unique_ptr<Command> duplicate_transition(std::string transition, std::string new_name) {
  std::string label = fmt::format("duplicate transition {} as {}", transition, new_name);
  return detail::list_edit(std::move(label), [=](Reconfigurable& scene) {
    const int index = detail::transition_index(scene, transition);
    detail::check_new_name(scene, "transition", new_name);
    Transition copy = scene.transitions[index];
    copy.name = new_name;
    scene.transitions.push_back(std::move(copy));
    return detail::transition_appended(scene);
  });
}

}  // namespace reconfig::scene
