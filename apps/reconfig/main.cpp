// reconfig — the command-line tool: scene information, spacetime collision checks, posing,
// linkages. Each subcommand lives in its own <name>_command.cpp.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "command.h"
#include "reconfig/common/input_error.h"

int main(int argc, char** argv) {
  using namespace reconfig::cli;
  CLI::App app{"reconfig — design reconfigurables: spacetime collision detection and more"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "reconfig 0.1.0");
  int exit_code = kExitOk;
  for (CommandRegistrar add : {add_info_command, add_check_command, add_pose_command, add_linkage_command,
                               add_ccd_queries_command, add_render_command, add_resolve_command, add_sweep_command,
                               add_carve_command, add_bench_command, add_sculpt_command})
    add(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? kExitOk : kExitBadInput;
  } catch (const reconfig::InputError& error) {
    std::fprintf(stderr, "reconfig: error: %s\n", error.what());
    return kExitBadInput;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "reconfig: error: %s\n", error.what());
    return kExitBadInput;
  }
  return exit_code;
}
