#include "reconfig/common/read_input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>

#include "reconfig/common/input_error.h"
#include "support/test_data.h"

namespace reconfig {
namespace {

namespace fs = std::filesystem;

std::string message_of(const fs::path& path, std::uintmax_t max_bytes = kMaxInputFileBytes) {
  try {
    read_input_file(path, max_bytes);
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), path.string());
    return error.message();
  }
  ADD_FAILURE() << "read " << path;
  return "";
}

TEST(ReadInputFile, ReadsARegularFileWhole) {
  const fs::path file = testing::fresh_temp_dir() / "a.txt";
  std::ofstream(file, std::ios::binary) << std::string("abc\0def", 7);
  EXPECT_EQ(read_input_file(file), std::string("abc\0def", 7));
  EXPECT_EQ(check_input_file(file), 7u);
  fs::create_symlink(file, file.parent_path() / "link.txt");
  EXPECT_EQ(read_input_file(file.parent_path() / "link.txt").size(), 7u);
}

TEST(ReadInputFile, RefusesWhatIsNoFileToRead) {
  const fs::path dir = testing::fresh_temp_dir();
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", dir / "zero");
  fs::create_symlink("loop", dir / "loop");
  EXPECT_EQ(message_of(dir / "fifo"), "is not a regular file (a FIFO)");  // without waiting for a writer
  EXPECT_EQ(message_of(dir / "zero"), "is not a regular file (a character device)");
  EXPECT_EQ(message_of("/dev/urandom"), "is not a regular file (a character device)");
  EXPECT_EQ(message_of(dir), "is a folder, not a file");
  EXPECT_EQ(message_of(dir / "missing"), "file not found");
  EXPECT_EQ(message_of(dir / "loop"), "cannot read the file: Too many levels of symbolic links");
  try {
    check_input_file(dir / "fifo");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.message(), "is not a regular file (a FIFO)");
  }
}

TEST(ReadInputFile, RefusesAFileBeyondTheLimitWithItsSize) {
  const fs::path file = testing::fresh_temp_dir() / "big";
  std::ofstream(file).close();
  fs::resize_file(file, 3u << 20);  // sparse
  EXPECT_EQ(message_of(file, 1u << 20), "is 3145728 bytes (3 MiB), more than the 1048576 bytes (1 MiB) a loader reads");
  EXPECT_EQ(read_input_file(file, 3u << 20).size(), 3u << 20);
}

}  // namespace
}  // namespace reconfig
