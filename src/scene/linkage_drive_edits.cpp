#include "reconfig/scene/linkage_drive_edits.h"

#include <fmt/format.h>

#include <set>

#include "reconfig/common/input_error.h"
#include "reconfig/scene/reconfigurable.h"
#include "reconfig/scene/validate_scene.h"

namespace reconfig::scene {
namespace {

/// What the edit changes: one transition and the states (their driven-part poses).
struct DriveSlice {
  Transition transition;
  std::vector<State> states;
};

class SetLinkageDrive final : public Command {
 public:
  SetLinkageDrive(std::string transition, std::optional<LinkageDrive> drive)
      : name_(std::move(transition)), drive_(std::move(drive)) {}

  DirtySet apply(Reconfigurable& scene) override {
    const int index = scene.find_transition(name_);
    if (index < 0) throw InputError("", "", fmt::format("unknown transition \"{}\"", name_));
    if (after_) {
      restore(scene, index, *after_);
      return dirty_;
    }
    DriveSlice before{scene.transitions[index], scene.states};
    try {
      Transition& transition = scene.transitions[index];
      if (drive_) {
        // The old drive's compiled tracks go; the new drive compiles its own.
        if (transition.linkage)
          for (const auto& [part, track] : transition.linkage->compiled) transition.tracks.erase(part);
        for (const LinkageAttachment& a : drive_->attach) transition.tracks.erase(a.part);
        transition.linkage = drive_;
        transition.linkage->compiled.clear();
        compile_linkage_drive(scene, index, DriveStatePoses::kOverwrite);
      } else {
        transition.linkage.reset();  // the compiled tracks stay as plain screw tracks
      }
      validate_scene(scene);
    } catch (...) {
      restore(scene, index, before);
      throw;
    }
    dirty_ = dirty(scene, before.transition);
    after_ = DriveSlice{scene.transitions[index], scene.states};
    before_ = std::move(before);
    return dirty_;
  }

  DirtySet revert(Reconfigurable& scene) override {
    restore(scene, scene.find_transition(name_), *before_);
    return dirty_;
  }

  std::string label() const override {
    return drive_ ? fmt::format("set the linkage drive of {}", name_) : fmt::format("remove the linkage drive of {}", name_);
  }

 private:
  static void restore(Reconfigurable& scene, int index, const DriveSlice& slice) {
    scene.transitions[index] = slice.transition;
    scene.states = slice.states;
  }

  /// Every part the old or new drive carries, over every transition touching the end states.
  DirtySet dirty(const Reconfigurable& scene, const Transition& old) const {
    std::set<std::string> parts;
    for (const std::optional<LinkageDrive>* d : {&old.linkage, &drive_})
      if (*d)
        for (const LinkageAttachment& a : (*d)->attach) parts.insert(a.part);
    DirtySet dirty;
    for (int tr = 0; tr < static_cast<int>(scene.transitions.size()); ++tr) {
      const Transition& t = scene.transitions[tr];
      const bool touches = t.name == name_ || t.from == old.from || t.from == old.to || t.to == old.from ||
                           t.to == old.to;
      if (!touches) continue;
      for (const std::string& part : parts)
        if (const int p = scene.find_part(part); p >= 0) dirty.ranges.push_back({tr, p, 0.0, 1.0});
    }
    return dirty;
  }

  std::string name_;
  std::optional<LinkageDrive> drive_;
  std::optional<DriveSlice> before_, after_;
  DirtySet dirty_;
};

}  // namespace

std::unique_ptr<Command> set_linkage_drive(std::string transition, std::optional<LinkageDrive> drive) {
  return std::make_unique<SetLinkageDrive>(std::move(transition), std::move(drive));
}

}  // namespace reconfig::scene
