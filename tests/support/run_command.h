#pragma once
/// @file
/// Runs a command line (the `reconfig` tool) and captures what it printed and its exit code.

#include <string>
#include <vector>

namespace reconfig::testing {

struct CommandResult {
  int exit_code = -1;
  std::string out;  ///< standard output
  std::string err;  ///< standard error
};

/// Runs `build/bin/<tool> <arguments>` through the shell (arguments are not quoted).
CommandResult run_tool(const std::string& tool, const std::string& arguments);

/// Runs `build/bin/reconfig <arguments>`.
CommandResult run_reconfig(const std::string& arguments);

/// Runs `build/bin/reconfig <arguments>` and presses Ctrl+C once it is catching SIGINT (its
/// Ctrl+C guard is in place, as /proc shows), however slowly it starts. `exit_code` is -1 if
/// it was killed by a signal; `err` says so if it finished before catching SIGINT at all.
CommandResult run_reconfig_interrupted(const std::vector<std::string>& arguments);

}  // namespace reconfig::testing
