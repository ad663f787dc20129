#pragma once
/// @file
/// Runs a command line (the `reconfig` tool) and captures what it printed and its exit code.

#include <string>

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

}  // namespace reconfig::testing
