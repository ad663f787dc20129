// A script's `click-part PART` fails, with a message, when the click selects another part (one
// in front of PART) or nothing, instead of passing with the wrong part selected.

#include <gtest/gtest.h>

#include <fstream>

#include "frontend.h"
#include "script.h"
#include "support/test_data.h"

namespace reconfig::studio {
namespace {

/// A small box inside a big one: from any side the big one is in front of the small one's center.
std::filesystem::path nested_boxes() {
  const std::filesystem::path file = testing::fresh_temp_dir() / "nested.json";
  std::ofstream(file) << R"({"format": "reconfig-scene", "version": 1,
    "parts": [{"name": "shell", "box": {"size": [1, 1, 1]}}, {"name": "core", "box": {"size": [0.2, 0.2, 0.2]}}],
    "states": [{"name": "rest", "poses": {}}]})";
  return file;
}

class ScriptClickPart : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(frontend_.studio().open(nested_boxes())) << frontend_.studio().status();
    frontend_.run_frame();
  }
  HeadlessFrontend frontend_{800, 600};
};

TEST_F(ScriptClickPart, SelectsTheVisiblePartItNames) {
  EXPECT_NO_THROW(run_script(frontend_, "click-part shell\nexpect-selected shell\n", "visible.txt"));
}

TEST_F(ScriptClickPart, FailsWhenAnotherPartIsInFront) {
  try {
    run_script(frontend_, "click-part core\n", "hidden.txt");
    FAIL() << "the click selected the shell, and the script passed";
  } catch (const ScriptError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("hidden.txt:1: click-part core: the click at ("), std::string::npos) << message;
    EXPECT_NE(message.find("selected shell (it is in front of the part)"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace reconfig::studio
