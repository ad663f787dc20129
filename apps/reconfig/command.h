#pragma once
/// @file
/// How the `reconfig` tool's subcommands plug into main: each lives in its own
/// `<name>_command.cpp` and registers itself with one `add_<name>_command` function.

#include <CLI/CLI.hpp>

#include "reconfig/scene/scene_file.h"

namespace reconfig::cli {

/// Exit codes scripts rely on (FORMATS.md).
enum ExitCode : int {
  kExitOk = 0,          ///< success; for `check`: collision-free
  kExitCollisions = 1,  ///< `check` found collisions
  kExitBadInput = 2,    ///< bad input: missing file, malformed data, bad arguments
  kExitInterrupted = 130,  ///< Ctrl+C stopped a long command (`check`): no result
};

/// Registers a subcommand on `app`. Its callback runs the command and stores the process
/// exit code in `exit_code`; a bad-input failure is thrown as `reconfig::InputError` and
/// turned into a one-line message and exit code 2 by main.
using CommandRegistrar = void (*)(CLI::App& app, int& exit_code);

/// `--allow-outside-paths` on a command that loads a scene: its mesh paths (and a glTF mesh's
/// buffer and image URIs) may then lead outside the scene's folder.
inline void add_allow_outside_paths_flag(CLI::App& command, scene::SceneLoadOptions& load) {
  command.add_flag("--allow-outside-paths", load.allow_outside_paths,
                   "Let the scene read meshes outside its folder (absolute paths, \"..\", symbolic links out)");
}

void add_info_command(CLI::App& app, int& exit_code);
void add_check_command(CLI::App& app, int& exit_code);
void add_pose_command(CLI::App& app, int& exit_code);
void add_linkage_command(CLI::App& app, int& exit_code);
void add_render_command(CLI::App& app, int& exit_code);
void add_ccd_queries_command(CLI::App& app, int& exit_code);
void add_bench_command(CLI::App& app, int& exit_code);
void add_resolve_command(CLI::App& app, int& exit_code);
void add_sculpt_command(CLI::App& app, int& exit_code);
void add_sweep_command(CLI::App& app, int& exit_code);
void add_carve_command(CLI::App& app, int& exit_code);

}  // namespace reconfig::cli
