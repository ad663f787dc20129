// command_sequence: several edits applied as one undoable step.

#include <utility>

#include "reconfig/scene/edits.h"

namespace reconfig::scene {
namespace {

class CommandSequence final : public Command {
 public:
  CommandSequence(std::string label, std::vector<std::unique_ptr<Command>> steps)
      : label_(std::move(label)), steps_(std::move(steps)) {}

  /// Applies the steps in order; when one is refused, those before it are reverted and the
  /// refusal goes on to the caller, so the scene is as it was.
  DirtySet apply(Reconfigurable& scene) override {
    DirtySet dirty;
    std::size_t applied = 0;
    try {
      for (; applied < steps_.size(); ++applied) dirty.merge(steps_[applied]->apply(scene));
    } catch (...) {
      while (applied > 0) steps_[--applied]->revert(scene);
      throw;
    }
    return dirty;
  }

  DirtySet revert(Reconfigurable& scene) override {
    DirtySet dirty;
    for (auto step = steps_.rbegin(); step != steps_.rend(); ++step) dirty.merge((*step)->revert(scene));
    return dirty;
  }

  std::string label() const override { return label_; }

 private:
  std::string label_;
  std::vector<std::unique_ptr<Command>> steps_;
};

}  // namespace

std::unique_ptr<Command> command_sequence(std::string label, std::vector<std::unique_ptr<Command>> steps) {
  return std::make_unique<CommandSequence>(std::move(label), std::move(steps));
}

}  // namespace reconfig::scene
