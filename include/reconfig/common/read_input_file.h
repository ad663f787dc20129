#pragma once
/// @file
/// Reading a user's file whole, refusing what is no file to read (a FIFO, a device, a folder)
/// and files beyond a size limit.

#include <cstdint>
#include <filesystem>
#include <string>

namespace reconfig {

/// The largest file a loader reads: 1 GiB, well above real meshes and scenes
/// (docs/file-formats.md, "Limits").
inline constexpr std::uintmax_t kMaxInputFileBytes = std::uintmax_t{1} << 30;

/// Checks that `path` is a regular file (symbolic links followed) of at most `max_bytes`, and
/// returns its size. A FIFO would block a reader forever, `/dev/zero` would fill the memory.
/// @throws InputError naming `path`: "file not found", "is a folder", "is not a regular file
///   (a FIFO)", "is 2.1 GB, more than the 1 GiB a loader reads", or the file system's own
///   reason (a symbolic link loop, no permission)
std::uintmax_t check_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes = kMaxInputFileBytes);

/// The bytes of `path`, after the checks of `check_input_file` (made on the opened file, so a
/// file swapped for a FIFO in between is refused too).
/// @throws InputError naming `path`
std::string read_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes = kMaxInputFileBytes);

}  // namespace reconfig
