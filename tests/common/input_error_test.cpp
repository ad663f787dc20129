#include "reconfig/common/input_error.h"

#include <gtest/gtest.h>

namespace reconfig {
namespace {

TEST(InputError, JoinsFileLocationAndMessageOnOneLine) {
  const InputError error("scene.json", "parts[2].mesh", "file not found");
  EXPECT_STREQ(error.what(), "scene.json: parts[2].mesh: file not found");
  EXPECT_EQ(error.file(), "scene.json");
  EXPECT_EQ(error.location(), "parts[2].mesh");
  EXPECT_EQ(error.message(), "file not found");
}

TEST(InputError, OmitsEmptyParts) {
  EXPECT_STREQ(InputError("", "", "bad").what(), "bad");
  EXPECT_STREQ(InputError("a.obj", "", "empty mesh").what(), "a.obj: empty mesh");
}

TEST(InputError, InFileKeepsLocationAndMessage) {
  const InputError error = InputError("", "states[0]", "unknown part").in_file("x.json");
  EXPECT_STREQ(error.what(), "x.json: states[0]: unknown part");
}

}  // namespace
}  // namespace reconfig
