#pragma once
/// @file
/// Whether a path written in a file (a scene's mesh path, a glTF buffer URI) stays inside the
/// file's own folder: a design someone sends you must not read your other files.

#include <filesystem>
#include <string>

namespace reconfig {

/// Why `reference`, a path written in a file in `folder`, leads outside that folder (an
/// absolute path, `..` out of it, or a symbolic link that points out), or "" if it stays
/// inside. Both are resolved through symbolic links.
/// @throws InputError (no file, no location) if the file system cannot resolve them (a
///   symbolic link loop), naming `reference`
std::string outside_folder_problem(const std::filesystem::path& folder, const std::string& reference);

}  // namespace reconfig
