#pragma once
/// @file
/// Scripted studio sessions: a text file of UI actions replayed through the headless frontend,
/// one per line (`#` starts a comment). Mouse and key actions go through ImGui exactly like a
/// user's; a few actions aim at named things (a part, a graph edge, a gizmo handle, a time on
/// the timeline) by asking the studio where they are drawn. `expect-…` lines check what the
/// UI shows and stop the script with an error naming the line. docs/studio.md lists them all.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "frontend.h"

namespace reconfig::studio {

/// A script line that cannot run or whose expectation failed.
class ScriptError : public std::runtime_error {
 public:
  ScriptError(const std::string& file, int line, const std::string& message);
};

/// Runs the actions of `script_text` (named `label` in errors) on `frontend`.
/// Relative paths in the script are taken from the current directory.
/// @throws ScriptError at the first failing line
void run_script(HeadlessFrontend& frontend, const std::string& script_text, const std::string& label);

}  // namespace reconfig::studio
