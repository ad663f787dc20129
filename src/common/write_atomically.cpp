#include "reconfig/common/write_atomically.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>

#include "reconfig/common/input_error.h"

namespace reconfig {
namespace fs = std::filesystem;

namespace {

fs::path temporary_of(const fs::path& path) {
  fs::path temp = path;
  temp += ".tmp";
  return temp;
}

/// Flushes `path` (a file or a folder) to the disk; returns whether that worked.
bool sync(const fs::path& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) return false;
  const bool synced = ::fsync(fd) == 0;
  ::close(fd);
  return synced;
}

[[noreturn]] void fail(const fs::path& path, const fs::path& temp, const std::string& message) {
  std::error_code ignored;
  fs::remove(temp, ignored);
  throw InputError(path.string(), "", message);
}

}  // namespace

void write_atomically(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  const fs::path temp = temporary_of(path);
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);  // replaces a stale one a kill left behind
    if (!out) throw InputError(path.string(), "", std::string("cannot open for writing: ") + std::strerror(errno));
    write(out);
    out.flush();
    if (!out) fail(path, temp, "write failed");
  }
  // The data reaches the disk before the rename does, so a power cut leaves the old file or the new one.
  if (!sync(temp, O_WRONLY)) fail(path, temp, std::string("cannot flush to the disk: ") + std::strerror(errno));
  std::error_code error;
  fs::rename(temp, path, error);
  if (error) fail(path, temp, "cannot replace the file: " + error.message());
  const fs::path folder = fs::absolute(path).parent_path();
  if (!sync(folder, O_RDONLY | O_DIRECTORY))  // the rename itself
    throw InputError(path.string(), "", std::string("cannot flush the folder to the disk: ") + std::strerror(errno));
}

void remove_stale_temporary(const fs::path& path) {
  std::error_code ignored;
  fs::remove(temporary_of(path), ignored);
}

}  // namespace reconfig
