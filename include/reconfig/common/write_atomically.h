#pragma once
/// @file
/// Writing a file so that a crash or a full disk never leaves a half-written one.

#include <filesystem>
#include <functional>
#include <ostream>

namespace reconfig {

/// Writes through `write` into `<path>.tmp`, then renames it over `path`: readers see the old
/// file or the complete new one, never a part. On failure the temporary file is removed and
/// the old file is left as it was.
/// @throws InputError naming `path` if the file cannot be opened, written or replaced
void write_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);

}  // namespace reconfig
