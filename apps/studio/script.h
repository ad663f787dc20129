#pragma once
/// @file
/// Scripted studio sessions: a text file of UI actions replayed through the headless frontend,
/// one per line (`#` starts a comment). Mouse and key actions go through ImGui exactly like a
/// user's; a few actions aim at named things (a part, a graph edge, a gizmo handle, a time on
/// the timeline) by asking the studio where they are drawn. `expect-…` lines check what the
/// UI shows and stop the script with an error naming the line. docs/studio.md lists them all.

#include <filesystem>
#include <optional>
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

/// `steps` + 1 evenly spaced points from a to b, both included (a drag's path).
std::vector<ImVec2> segment(ImVec2 a, ImVec2 b, int steps);

/// Runs frames with the mouse at each point in turn, the button held from the first to the
/// last (a press, a drag through the points, a release); `wheel` steps of the mouse wheel at
/// the middle point.
void drag_through(HeadlessFrontend& frontend, const std::vector<ImVec2>& points, int button = 0, float wheel = 0);

/// The whole of `text` read as a finite number, or nothing (a script's numeric argument).
std::optional<double> script_number(const std::string& text);

/// Runs one of the linkage panel's actions (`linkage-…`, linkage_script.cpp).
/// @throws std::runtime_error saying what failed
void run_linkage_action(HeadlessFrontend& frontend, const std::string& action, const std::vector<std::string>& args);

/// Runs the actions of `script_text` (named `label` in errors) on `frontend`.
/// Relative paths in the script are taken from the current directory.
/// @throws ScriptError at the first failing line
void run_script(HeadlessFrontend& frontend, const std::string& script_text, const std::string& label);

}  // namespace reconfig::studio
