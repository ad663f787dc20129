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

TEST(InputError, ControlCharactersAreEscapedInWhat) {
  const InputError error("", "parts[0].name", "unknown part \"\x1b[31mred\n\"");
  EXPECT_STREQ(error.what(), "parts[0].name: unknown part \"\\x1b[31mred\\x0a\"");
  EXPECT_EQ(error.message(), "unknown part \"\x1b[31mred\n\"");  // the accessors keep the data
}

TEST(InputError, EachPartIsBoundedInWhat) {
  const std::string huge(50'000'000, '[');
  const InputError error("f.json", huge, "unsupported version " + huge);
  EXPECT_LT(std::string(error.what()).size(), 3 * kMaxInputErrorPart);
  EXPECT_NE(std::string(error.what()).find("(50000020 characters in all)"), std::string::npos);
}

TEST(InputError, ACutNeverSplitsAUtf8Character) {
  std::string text;
  while (text.size() < 2 * kMaxInputErrorPart) text += "é";
  const std::string shown = InputError("", "", text).what();
  EXPECT_EQ(shown.substr(0, shown.find("…")).size() % 2, 0u) << "a split two-byte character";
}

}  // namespace
}  // namespace reconfig
