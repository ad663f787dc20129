#pragma once
/// @file
/// The script actions that author a design (docs/file-formats.md, "Studio scripts"): new,
/// import, add-primitive, the part, state and transition edits, set-pose, set-handle,
/// show-state, undo, redo and the expectations about the design's lists. They call the same
/// studio actions as the menus.

#include <functional>
#include <string>
#include <vector>

#include "frontend.h"

namespace reconfig::studio {

/// Performs `action` with `args` if it is an authoring action (then returns true; false when
/// it is not one). A refused edit or a failed expectation calls `fail` with the reason.
bool run_authoring_action(HeadlessFrontend& frontend, const std::string& action, const std::vector<std::string>& args,
                          const std::function<void(const std::string&)>& fail);

}  // namespace reconfig::studio
