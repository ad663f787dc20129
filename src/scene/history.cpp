#include "reconfig/scene/history.h"

namespace reconfig::scene {

DirtySet History::execute(Reconfigurable& scene, std::unique_ptr<Command> command) {
  DirtySet dirty = command->apply(scene);  // throws before anything is recorded
  commands_.resize(applied_);
  commands_.push_back(std::move(command));
  applied_ = commands_.size();
  return dirty;
}

DirtySet History::undo(Reconfigurable& scene) {
  if (!can_undo()) return {};
  return commands_[--applied_]->revert(scene);
}

DirtySet History::redo(Reconfigurable& scene) {
  if (!can_redo()) return {};
  return commands_[applied_++]->apply(scene);
}

std::string History::undo_label() const { return can_undo() ? commands_[applied_ - 1]->label() : ""; }
std::string History::redo_label() const { return can_redo() ? commands_[applied_]->label() : ""; }

}  // namespace reconfig::scene
