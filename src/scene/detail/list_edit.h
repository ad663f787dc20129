#pragma once
/// @file
/// The command behind the edits of a design's lists (parts, states, transitions): it runs an
/// edit once, validates the design, and keeps what the lists were before and after so undo
/// and redo restore them exactly, copying only the meshes of parts that one side lacks.

#include <functional>
#include <memory>
#include <string>

#include "reconfig/scene/command.h"

namespace reconfig::scene::detail {

/// Refuses an edit: throws InputError with `message` (no file, no JSON path).
[[noreturn]] void refuse(const std::string& message);

/// Refuses `name` as the new name of a `kind` ("part", "state", "transition") when it is
/// empty or another one of that kind has it.
void check_new_name(const Reconfigurable& scene, const std::string& kind, const std::string& name);

/// Index of the part / state / transition named `name`; refuses when there is none.
int part_index(const Reconfigurable& scene, const std::string& name);
int state_index(const Reconfigurable& scene, const std::string& name);
int transition_index(const Reconfigurable& scene, const std::string& name);

/// An edit that may change the parts (add, remove, rename, recolor: not their meshes), the
/// states and the transitions. `edit` runs at the first apply only and says what it dirtied;
/// when it throws, or the design it leaves is invalid (validate_scene), everything is restored
/// and the refusal is rethrown.
using ListMutation = std::function<DirtySet(Reconfigurable&)>;
std::unique_ptr<Command> list_edit(std::string label, ListMutation edit);

/// The dirty set of a change of the lists themselves (indices shift: detect everything again).
DirtySet structure_changed();
/// The dirty set of a transition appended to `scene`'s list (its last): detect it alone. Its
/// undo reports `structure_changed`.
DirtySet transition_appended(const Reconfigurable& scene);

}  // namespace reconfig::scene::detail
