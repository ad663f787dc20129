#include "reconfig/scene/track.h"

#include <algorithm>

namespace reconfig::scene {

motion::Pose evaluate_track(const Track& track, double t, const motion::Pose& hold, const Eigen::Vector3d& center) {
  if (const auto* screw = std::get_if<ScrewPosesTrack>(&track)) {
    // Only the keys around t matter: the result is the same, bit for bit, as evaluating the
    // whole track, without building a screw per segment (driven tracks have hundreds).
    const auto& keys = screw->poses;
    if (keys.size() <= 2) return motion::ScrewTrack(keys, center).evaluate(t);
    if (!(t > keys.front().time)) return motion::ScrewTrack({keys.front()}, center).evaluate(t);
    if (!(t < keys.back().time)) return motion::ScrewTrack({keys.back()}, center).evaluate(t);
    const auto after = std::upper_bound(keys.begin(), keys.end(), t,
                                        [](double time, const motion::ScrewKey& key) { return time < key.time; });
    return motion::ScrewTrack({*std::prev(after), *after}, center).evaluate(t);
  }
  const auto& keyed = std::get<KeyframedTrack>(track);
  motion::Pose pose = hold;
  if (!keyed.translation.empty()) pose.translation = motion::BezierTranslationTrack(keyed.translation).evaluate(t);
  if (!keyed.rotation.empty()) pose.rotation = motion::SlerpRotationTrack(keyed.rotation).evaluate(t);
  return pose;
}

motion::Pose track_end_pose(const Track& track, bool at_end, const motion::Pose& hold) {
  if (const auto* screw = std::get_if<ScrewPosesTrack>(&track))
    return at_end ? screw->poses.back().pose : screw->poses.front().pose;
  const auto& keyed = std::get<KeyframedTrack>(track);
  motion::Pose pose = hold;
  if (!keyed.translation.empty())
    pose.translation = at_end ? keyed.translation.back().point : keyed.translation.front().point;
  if (!keyed.rotation.empty()) pose.rotation = at_end ? keyed.rotation.back().rotation : keyed.rotation.front().rotation;
  return pose;
}

std::vector<double> key_times(const Track& track) {
  std::vector<double> times;
  if (const auto* screw = std::get_if<ScrewPosesTrack>(&track)) {
    for (const auto& key : screw->poses) times.push_back(key.time);
  } else {
    const auto& keyed = std::get<KeyframedTrack>(track);
    for (const auto& key : keyed.translation) times.push_back(key.time);
    for (const auto& key : keyed.rotation) times.push_back(key.time);
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

}  // namespace reconfig::scene
