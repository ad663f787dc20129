// set_transition_tracks: several parts' tracks of one transition replaced in one step.

#include <fmt/format.h>

#include <optional>

#include "reconfig/common/input_error.h"
#include "reconfig/scene/edits.h"
#include "reconfig/scene/validate_scene.h"

namespace reconfig::scene {
namespace {

class TransitionTracksEdit final : public Command {
 public:
  TransitionTracksEdit(std::string transition, std::map<std::string, Track> tracks, std::string label)
      : transition_(std::move(transition)), after_(std::move(tracks)), label_(std::move(label)) {}

  DirtySet apply(Reconfigurable& scene) override {
    Transition& tr = transition(scene);
    std::map<std::string, std::optional<Track>> before;
    for (const auto& [part, track] : after_) {
      if (scene.find_part(part) < 0) throw InputError("", "", fmt::format("unknown part \"{}\"", part));
      const auto it = tr.tracks.find(part);
      before[part] = it == tr.tracks.end() ? std::nullopt : std::optional(it->second);
    }
    for (const auto& [part, track] : after_) tr.tracks[part] = track;
    try {
      validate_scene(scene);
    } catch (...) {
      restore(tr, before);
      throw;
    }
    before_ = std::move(before);
    return dirty(scene);
  }

  DirtySet revert(Reconfigurable& scene) override {
    restore(transition(scene), before_);
    return dirty(scene);
  }

  std::string label() const override { return label_; }

 private:
  Transition& transition(Reconfigurable& scene) const {
    const int index = scene.find_transition(transition_);
    if (index < 0) throw InputError("", "", fmt::format("unknown transition \"{}\"", transition_));
    return scene.transitions[index];
  }
  static void restore(Transition& tr, const std::map<std::string, std::optional<Track>>& tracks) {
    for (const auto& [part, track] : tracks) {
      if (track) tr.tracks[part] = *track;
      else tr.tracks.erase(part);
    }
  }
  /// Every replaced part's motion over the whole transition.
  DirtySet dirty(const Reconfigurable& scene) const {
    DirtySet set;
    const int tr = scene.find_transition(transition_);
    for (const auto& [part, track] : after_) set.ranges.push_back({tr, scene.find_part(part), 0.0, 1.0});
    return set;
  }

  std::string transition_;
  std::map<std::string, Track> after_;
  std::map<std::string, std::optional<Track>> before_;
  std::string label_;
};

}  // namespace

std::unique_ptr<Command> set_transition_tracks(std::string transition, std::map<std::string, Track> tracks,
                                               std::string label) {
  return std::make_unique<TransitionTracksEdit>(std::move(transition), std::move(tracks), std::move(label));
}

}  // namespace reconfig::scene
