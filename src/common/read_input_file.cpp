#include "reconfig/common/read_input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include <cerrno>
#include <cstring>

#include "reconfig/common/input_error.h"

namespace reconfig {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& message) {
  throw InputError(path.string(), "", message);
}

[[noreturn]] void fail_errno(const std::filesystem::path& path, int error) {
  fail(path, error == ENOENT ? "file not found" : fmt::format("cannot read the file: {}", std::strerror(error)));
}

std::string size_text(std::uintmax_t bytes) {
  const auto size = static_cast<double>(bytes);
  if (bytes >= (1u << 30)) return fmt::format("{} bytes ({:.3g} GiB)", bytes, size / (1u << 30));
  if (bytes >= (1u << 20)) return fmt::format("{} bytes ({:.3g} MiB)", bytes, size / (1u << 20));
  return fmt::format("{} bytes", bytes);
}

const char* kind_of(mode_t mode) {
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a file";
}

/// Refuses what `status` shows is no regular file of at most `max_bytes`; returns the size.
std::uintmax_t check_status(const std::filesystem::path& path, const struct stat& status, std::uintmax_t max_bytes) {
  if (S_ISDIR(status.st_mode)) fail(path, "is a folder, not a file");
  if (!S_ISREG(status.st_mode)) fail(path, fmt::format("is not a regular file ({})", kind_of(status.st_mode)));
  const auto size = static_cast<std::uintmax_t>(status.st_size);
  if (size > max_bytes)
    fail(path, fmt::format("is {}, more than the {} a loader reads", size_text(size), size_text(max_bytes)));
  return size;
}

class FileDescriptor {
 public:
  explicit FileDescriptor(int fd) : fd_(fd) {}
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  ~FileDescriptor() { ::close(fd_); }
  int get() const { return fd_; }

 private:
  int fd_;
};

}  // namespace

std::uintmax_t check_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) fail_errno(path, errno);
  return check_status(path, status, max_bytes);
}

std::string read_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes) {
  // O_NONBLOCK: opening a FIFO must not wait for a writer before fstat can refuse it.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) fail_errno(path, errno);
  const FileDescriptor file(fd);
  struct stat status {};
  if (::fstat(fd, &status) != 0) fail_errno(path, errno);
  const std::uintmax_t size = check_status(path, status, max_bytes);
  std::string bytes(size, '\0');
  std::size_t done = 0;
  while (done < size) {  // a file that shrinks meanwhile ends early; one that grows is read to its old size
    const ssize_t n = ::read(fd, bytes.data() + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail_errno(path, errno);
    if (n == 0) break;
    done += static_cast<std::size_t>(n);
  }
  bytes.resize(done);
  return bytes;
}

}  // namespace reconfig
