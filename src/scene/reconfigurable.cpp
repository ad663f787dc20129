#include "reconfig/scene/reconfigurable.h"

#include <cassert>
#include <variant>

namespace reconfig::scene {
namespace {

template <typename Named>
int find_by_name(const std::vector<Named>& items, const std::string& name) {
  for (std::size_t i = 0; i < items.size(); ++i)
    if (items[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace

int Reconfigurable::find_part(const std::string& name) const { return find_by_name(parts, name); }
int Reconfigurable::find_state(const std::string& name) const { return find_by_name(states, name); }
int Reconfigurable::find_transition(const std::string& name) const { return find_by_name(transitions, name); }

const KeyframedTrack* Reconfigurable::keyframed_track(int transition, int part) const {
  const auto& tracks = transitions.at(transition).tracks;
  const auto it = tracks.find(parts.at(part).name);
  return it == tracks.end() ? nullptr : std::get_if<KeyframedTrack>(&it->second);
}

motion::Pose Reconfigurable::pose_at(int transition, int part, double t) const {
  const Transition& tr = transitions.at(transition);
  const Part& p = parts.at(part);
  const int from = find_state(tr.from);
  assert(from >= 0 && "validated scenes name existing states");
  const motion::Pose hold = states.at(from).pose_of(p.name);
  const auto track = tr.tracks.find(p.name);
  if (track == tr.tracks.end()) return hold;
  return evaluate_track(track->second, t, hold, p.center);
}

Eigen::MatrixX3d Reconfigurable::posed_vertices(int transition, int part, double t) const {
  return posed_part_vertices(parts.at(part), pose_at(transition, part, t));
}

Eigen::MatrixX3d Reconfigurable::posed_vertices_in_state(int state, int part) const {
  const Part& p = parts.at(part);
  return posed_part_vertices(p, states.at(state).pose_of(p.name));
}

}  // namespace reconfig::scene
