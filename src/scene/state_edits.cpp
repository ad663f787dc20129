// Edits of the list of states: add, rename, delete.

#include "reconfig/scene/state_edits.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <vector>

#include "scene/detail/list_edit.h"

namespace reconfig::scene {

std::map<std::string, motion::Pose> current_poses(const Reconfigurable& scene, int transition, int state, double t) {
  std::map<std::string, motion::Pose> poses;
  for (int p = 0; p < static_cast<int>(scene.parts.size()); ++p) {
    const std::string& name = scene.parts[p].name;
    poses[name] = transition >= 0 ? scene.pose_at(transition, p, t) : scene.states.at(state).pose_of(name);
  }
  return poses;
}

std::unique_ptr<Command> add_state(std::string name, std::map<std::string, motion::Pose> poses) {
  std::string label = fmt::format("add state {}", name);
  return detail::list_edit(std::move(label), [=](Reconfigurable& scene) {
    detail::check_new_name(scene, "state", name);
    for (const auto& [part, pose] : poses) detail::part_index(scene, part);
    State state;
    state.name = name;
    state.poses = poses;
    for (auto& [part, pose] : state.poses) pose.rotation.normalize();
    scene.states.push_back(std::move(state));
    return DirtySet{};  // no transition uses it
  });
}

std::unique_ptr<Command> rename_state(std::string state, std::string new_name) {
  std::string label = fmt::format("rename state {} to {}", state, new_name);
  return detail::list_edit(std::move(label), [=](Reconfigurable& scene) {
    const int index = detail::state_index(scene, state);
    detail::check_new_name(scene, "state", new_name);
    scene.states[index].name = new_name;
    for (Transition& transition : scene.transitions) {
      if (transition.from == state) transition.from = new_name;
      if (transition.to == state) transition.to = new_name;
    }
    return DirtySet{};
  });
}

std::unique_ptr<Command> delete_state(std::string state, bool with_transitions) {
  std::string label = fmt::format("delete state {}", state);
  return detail::list_edit(std::move(label), [=](Reconfigurable& scene) {
    const int index = detail::state_index(scene, state);
    if (scene.states.size() == 1) detail::refuse(fmt::format("state \"{}\" is the design's only state: it keeps one", state));
    std::vector<std::string> using_it;
    for (const Transition& transition : scene.transitions)
      if (transition.from == state || transition.to == state) using_it.push_back("\"" + transition.name + "\"");
    if (!using_it.empty() && !with_transitions)
      detail::refuse(fmt::format("state \"{}\" is an end of {} {}: delete it with them, or delete them first", state,
                                 using_it.size() == 1 ? "transition" : "transitions", fmt::join(using_it, ", ")));
    scene.states.erase(scene.states.begin() + index);
    std::erase_if(scene.transitions, [&](const Transition& t) { return t.from == state || t.to == state; });
    return using_it.empty() ? DirtySet{} : detail::structure_changed();
  });
}

}  // namespace reconfig::scene
