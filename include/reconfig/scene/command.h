#pragma once
/// @file
/// Undoable edits of a reconfigurable.

#include <memory>
#include <string>

#include "reconfig/scene/dirty_set.h"
#include "reconfig/scene/reconfigurable.h"

namespace reconfig::scene {

/// One edit. `apply` performs it, `revert` undoes it; both report what they dirtied. A
/// command validates its arguments in `apply` and throws InputError (leaving the scene
/// untouched) when they make no sense, e.g. a key index out of range.
class Command {
 public:
  virtual ~Command() = default;
  virtual DirtySet apply(Reconfigurable& scene) = 0;
  virtual DirtySet revert(Reconfigurable& scene) = 0;
  /// Short, user-facing description ("move translation key 2 of seat").
  virtual std::string label() const = 0;
};

}  // namespace reconfig::scene
