#pragma once
/// @file
/// Writing a file so that a crash or a full disk never leaves a half-written one.

#include <filesystem>
#include <functional>
#include <ostream>

namespace reconfig {

/// Writes through `write` into `<path>.tmp`, flushes it to the disk, renames it over `path` and
/// flushes the folder: readers — and the disk after a power cut — see the old file or the
/// complete new one, never a part. On failure the temporary file is removed and the old file
/// is left as it was; a stale temporary from a killed write is replaced.
/// @throws InputError naming `path` if the file cannot be opened, written or replaced
void write_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);

/// Removes the `<path>.tmp` a write of `path` killed midway left behind (if any); call it when
/// opening `path`, so no stale temporary stays forever.
void remove_stale_temporary(const std::filesystem::path& path);

}  // namespace reconfig
