#pragma once
/// @file
/// Undo/redo over commands.

#include <memory>
#include <vector>

#include "reconfig/scene/command.h"

namespace reconfig::scene {

/// A linear undo history. Executing a new command drops the redo branch.
class History {
 public:
  /// Applies `command` to `scene` and records it. If `apply` throws, nothing is recorded.
  DirtySet execute(Reconfigurable& scene, std::unique_ptr<Command> command);
  /// Reverts the last applied command (empty set if none).
  DirtySet undo(Reconfigurable& scene);
  /// Re-applies the last undone command (empty set if none).
  DirtySet redo(Reconfigurable& scene);

  bool can_undo() const { return applied_ > 0; }
  bool can_redo() const { return applied_ < commands_.size(); }
  /// Label of what undo / redo would do ("" if nothing).
  std::string undo_label() const;
  std::string redo_label() const;

 private:
  std::vector<std::unique_ptr<Command>> commands_;
  std::size_t applied_ = 0;  ///< commands_[0, applied_) are applied
};

}  // namespace reconfig::scene
