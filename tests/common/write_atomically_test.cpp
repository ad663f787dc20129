#include "reconfig/common/write_atomically.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "reconfig/common/input_error.h"
#include "support/test_data.h"

namespace reconfig {
namespace {

namespace fs = std::filesystem;

std::string content(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(WriteAtomically, ReplacesTheFileAndLeavesNoTemporary) {
  const fs::path file = testing::fresh_temp_dir() / "scene.json";
  std::ofstream(file) << "old";
  write_atomically(file, [](std::ostream& out) { out << "new"; });
  EXPECT_EQ(content(file), "new");
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
}

TEST(WriteAtomically, AStaleTemporaryFromAKilledSaveIsReplacedOrRemoved) {
  const fs::path file = testing::fresh_temp_dir() / "scene.json";
  const fs::path stale = file.string() + ".tmp";
  std::ofstream(stale) << std::string(100'000, 'x');  // a save killed midway
  write_atomically(file, [](std::ostream& out) { out << "new"; });
  EXPECT_EQ(content(file), "new");
  EXPECT_FALSE(fs::exists(stale));
  std::ofstream(stale) << "half";
  remove_stale_temporary(file);
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_EQ(content(file), "new");
  EXPECT_NO_THROW(remove_stale_temporary(file));  // none left: nothing to do
}

TEST(WriteAtomically, AFailedWriteKeepsTheOldFile) {
  const fs::path file = testing::fresh_temp_dir() / "scene.json";
  std::ofstream(file) << "old";
  EXPECT_THROW(write_atomically(file, [](std::ostream& out) { out.setstate(std::ios::badbit); }), InputError);
  EXPECT_EQ(content(file), "old");
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
}

}  // namespace
}  // namespace reconfig
