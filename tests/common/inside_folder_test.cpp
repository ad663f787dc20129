#include "reconfig/common/inside_folder.h"

#include <gtest/gtest.h>

#include "reconfig/common/input_error.h"
#include "support/test_data.h"

namespace reconfig {
namespace {

namespace fs = std::filesystem;

TEST(InsideFolder, PathsThatStayInsideAreFine) {
  const fs::path dir = testing::fresh_temp_dir();
  fs::create_directories(dir / "meshes");
  fs::create_symlink("meshes", dir / "alias");
  for (const char* inside : {"a.obj", "meshes/a.obj", "meshes/../a.obj", "./meshes/./a.obj", "alias/a.obj", "missing/x"})
    EXPECT_EQ(outside_folder_problem(dir, inside), "") << inside;
  EXPECT_EQ(outside_folder_problem(dir.string() + "/", "a.obj"), "");
}

TEST(InsideFolder, PathsThatLeaveAreNamedWithTheWay) {
  const fs::path dir = testing::fresh_temp_dir();
  fs::create_directories(dir / "design");
  fs::create_symlink("..", dir / "design" / "up");
  const fs::path design = dir / "design";
  EXPECT_NE(outside_folder_problem(design, "/etc/passwd").find("\"/etc/passwd\" is an absolute path"), std::string::npos);
  EXPECT_NE(outside_folder_problem(design, "../../../../etc/passwd").find("with \"..\""), std::string::npos);
  EXPECT_NE(outside_folder_problem(design, "a/../../x").find("with \"..\""), std::string::npos);
  EXPECT_NE(outside_folder_problem(design, "up/x.obj").find("through a symbolic link"), std::string::npos);
  // Once normalized, missing/../up is up: the link is followed either way.
  EXPECT_NE(outside_folder_problem(design, "missing/../up/x.obj").find("through a symbolic link"), std::string::npos);
  EXPECT_NE(outside_folder_problem(design, "../x").find("--allow-outside-paths"), std::string::npos);
}

TEST(InsideFolder, ASymlinkLoopIsAnInputErrorNamingThePath) {
  const fs::path dir = testing::fresh_temp_dir();
  fs::create_symlink("loop", dir / "loop");
  try {
    outside_folder_problem(dir, "loop/a.obj");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_NE(error.message().find("cannot resolve \"loop/a.obj\""), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace reconfig
