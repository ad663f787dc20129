#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "support/run_command.h"
#include "studio_test_util.h"

namespace reconfig::studio {
namespace {

TEST(StudioCli, TheExampleSessionScriptPasses) {
  const std::filesystem::path scene = bench_table_copy();
  const auto result = testing::run_tool(
      "reconfig-studio", scene.string() + " --script " + (scene.parent_path() / "studio-session.txt").string());
  EXPECT_EQ(result.exit_code, 0) << result.err;
}

TEST(StudioCli, CollisionSettingsFromTheCommandLine) {
  const std::filesystem::path scene = bench_table_copy();
  const std::filesystem::path script = scene.parent_path() / "settings.txt";
  std::ofstream(script) << "expect-collision-settings tolerance=0.002 dop=80 box-resolution=0 conservative=on\n"
                           "wait-collisions\nclick-edge unfold\nexpect-collision-at 0.4\n";
  const auto result = testing::run_tool("reconfig-studio", scene.string() + " --script " + script.string() +
                                                               " --tolerance 0.002 --dop 80 --box-resolution 0 --conservative");
  EXPECT_EQ(result.exit_code, 0) << result.err;
  // The defaults are not those: the same expectation fails without the options.
  const auto defaults = testing::run_tool("reconfig-studio", scene.string() + " --script " + script.string());
  EXPECT_EQ(defaults.exit_code, 1);
  EXPECT_NE(defaults.err.find("settings.txt:1: the collision settings are not"), std::string::npos) << defaults.err;
  // Out of range: a usage error.
  EXPECT_EQ(testing::run_tool("reconfig-studio", scene.string() + " --headless --dop 7").exit_code, 2);
  EXPECT_EQ(testing::run_tool("reconfig-studio", scene.string() + " --headless --box-resolution 2").exit_code, 2);
  EXPECT_EQ(testing::run_tool("reconfig-studio", scene.string() + " --headless --tolerance -1").exit_code, 2);
}

TEST(StudioCli, AFailedExpectationNamesTheLineAndExitsOne) {
  const std::filesystem::path scene = bench_table_copy();
  const std::filesystem::path script = scene.parent_path() / "wrong.txt";
  std::ofstream(script) << "wait-collisions\n# the unfold choreography collides\nexpect-collisions 0\n";
  const auto result = testing::run_tool("reconfig-studio", scene.string() + " --script " + script.string());
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("wrong.txt:3: expected 0 collision intervals"), std::string::npos) << result.err;
}

TEST(StudioCli, ScreenshotWritesAPngOfTheWholeStudio) {
  const std::filesystem::path scene = bench_table_copy();
  const std::filesystem::path png = scene.parent_path() / "studio.png";
  const auto result = testing::run_tool("reconfig-studio", scene.string() + " --screenshot " + png.string() +
                                                               " --frames 3 --size 640x400 --frame-times " +
                                                               (scene.parent_path() / "times.json").string());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  std::ifstream in(png, std::ios::binary);
  char signature[8] = {};
  in.read(signature, 8);
  EXPECT_EQ(std::string(signature + 1, 3), "PNG");
  std::ifstream times(scene.parent_path() / "times.json");
  std::string json((std::istreambuf_iterator<char>(times)), {});
  EXPECT_NE(json.find("\"frames\": 3"), std::string::npos) << json;
}

TEST(StudioCli, ScreenshotWaitsForCollisionDetectionUnlessToldNotTo) {
  const std::filesystem::path scene = bench_table_copy();
  const std::filesystem::path png = scene.parent_path() / "waited.png";
  const auto waited =
      testing::run_tool("reconfig-studio", scene.string() + " --time 0.4 --size 640x400 --screenshot " + png.string());
  ASSERT_EQ(waited.exit_code, 0) << waited.err;
  EXPECT_EQ(waited.out, "wrote " + png.string() + " (collisions detected)\n");
  const auto at_once = testing::run_tool("reconfig-studio", scene.string() + " --size 640x400 --no-wait --screenshot " +
                                                                png.string());
  ASSERT_EQ(at_once.exit_code, 0) << at_once.err;
  EXPECT_EQ(at_once.out, "wrote " + png.string() + "\n");
}

// The desktop path (GLFW window, the ImGui GLFW backend, swapping) under a virtual X server.
TEST(StudioCli, TheWindowShowsTheStudioUnderXvfb) {
  if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run is not installed (./run deps)";
  const std::filesystem::path scene = bench_table_copy();
  const std::filesystem::path png = scene.parent_path() / "window.png";
  const std::string command = "xvfb-run -a -s '-screen 0 1024x768x24' " +
                              (testing::binary_dir() / "bin" / "reconfig-studio").string() + " " + scene.string() +
                              " --window --size 800x600 --frames 10 --screenshot " + png.string() + " >/dev/null 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0);
  EXPECT_GT(std::filesystem::file_size(png), 10000u);
}

TEST(StudioCli, BadInputExitsTwoWithAMessage) {
  const std::filesystem::path dir = testing::fresh_temp_dir();
  std::ofstream(dir / "broken.json") << "{ not json";
  auto result = testing::run_tool("reconfig-studio", (dir / "broken.json").string() + " --frames 1");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("broken.json"), std::string::npos) << result.err;
  result = testing::run_tool("reconfig-studio", "--size 12 --frames 1");
  EXPECT_EQ(result.exit_code, 2);
  const std::filesystem::path scene = bench_table_copy();
  result = testing::run_tool("reconfig-studio", scene.string() + " --script " + (dir / "none.txt").string());
  EXPECT_EQ(result.exit_code, 2);
  std::ofstream(dir / "typo.txt") << "clik 10 10\n";
  result = testing::run_tool("reconfig-studio", scene.string() + " --script " + (dir / "typo.txt").string());
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("typo.txt:1: unknown action \"clik\""), std::string::npos) << result.err;
}

}  // namespace
}  // namespace reconfig::studio
