// The `reconfig linkage` commands, run as a user would.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "linkage_test_util.h"
#include "reconfig/linkage/linkage_edit.h"
#include "support/run_command.h"
#include "support/test_data.h"

namespace reconfig::linkage {
namespace {

/// Runs the tool; these tests look for messages on either stream.
testing::CommandResult run(const std::string& arguments) {
  testing::CommandResult result = testing::run_reconfig(arguments);
  result.out += result.err;
  return result;
}

std::string example_path(const std::string& name) {
  return (testing::source_dir() / "examples" / "linkages" / name).string();
}

class LinkageCli : public ::testing::Test {};

TEST_F(LinkageCli, SimulatePrintsTheJsonContract) {
  const testing::CommandResult r = run("linkage simulate " + example_path("jansen.json") + " --angles 0,90,450 --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["angles"], nlohmann::json({0, 90, 450}));
  ASSERT_EQ(doc["joints"]["P"].size(), 3u);
  EXPECT_NEAR(doc["joints"]["C"][1][0].get<double>(), 0, 1e-12);
  EXPECT_NEAR(doc["joints"]["C"][1][1].get<double>(), 15, 1e-12);
  EXPECT_NEAR(doc["joints"]["P"][1][0].get<double>(), doc["joints"]["P"][2][0].get<double>(), 1e-9);  // 90° ≡ 450°
}

TEST_F(LinkageCli, SimulateFailsCleanlyPastADeadPointAndOnBadInput) {
  testing::CommandResult r = run("linkage simulate " + example_path("peaucellier_lipkin.json") + " --angles 10,120");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("hits a singularity at 82.819° before reaching 120°"), std::string::npos) << r.out;
  const auto dir = testing::fresh_temp_dir();
  { std::ofstream(dir / "bad.json") << R"({"format": "reconfig-linkage", "version": 1, "joints": []})"; }
  r = run("linkage simulate " + (dir / "bad.json").string() + " --angles 0");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("bad.json: joints: expected a non-empty array"), std::string::npos) << r.out;
  r = run("linkage simulate " + (dir / "missing.json").string() + " --angles 0");
  EXPECT_EQ(r.exit_code, 2);
}

/// The number after `prefix` in `text` (−1 if absent).
double number_after(const std::string& text, const std::string& prefix) {
  const auto at = text.find(prefix);
  return at == std::string::npos ? -1 : std::stod(text.substr(at + prefix.size()));
}

TEST_F(LinkageCli, EditFollowsTargetCurves) {
  const auto dir = testing::fresh_temp_dir();
  const std::string out = (dir / "edited.json").string();
  // Sample 54 of the foot's curve lifted by 8 (soft selection of radius 15): the target is 8
  // away from the foot's path there; the edit brings the path well within that.
  testing::CommandResult r = run("linkage edit " + example_path("jansen.json") + " --curve-drag foot 54 0 8 15 -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const double drag = number_after(r.out, "target curve of P: largest deviation ");
  EXPECT_GT(drag, 0) << r.out;
  EXPECT_LT(drag, 4) << r.out;
  EXPECT_NE(r.out.find("motion: full rotation"), std::string::npos) << r.out;
  const Linkage before = test::example("jansen.json"), after = read_linkage(out);
  const std::vector<double> angles = edit_sample_angles(before, 72);
  const int foot = before.find_joint("P");
  EXPECT_GT(joint_trajectory(after, foot, angles)[54].y() - joint_trajectory(before, foot, angles)[54].y(), 4);
  // The whole curve 10% smaller about its centroid, the rest of the motion kept.
  r = run("linkage edit " + example_path("jansen.json") + " --curve-transform foot 0.9 0 0 0 -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_GT(number_after(r.out, "target curve of P: largest deviation "), 0) << r.out;
  r = run("linkage edit " + example_path("jansen.json") + " --curve-drag foot 72 0 8 15 -o " + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("--curve-drag: INDEX must be a sample index 0 … 71, not 72"), std::string::npos) << r.out;
  r = run("linkage edit " + example_path("jansen.json") + " --curve-drag foot 3 0 8 -1 -o " + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("RADIUS must be ≥ 0"), std::string::npos) << r.out;
  r = run("linkage edit " + example_path("jansen.json") + " --curve-transform foot 0 0 0 0 -o " + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("SCALE must be > 0"), std::string::npos) << r.out;
  r = run("linkage edit " + example_path("jansen.json") + " --curve-transform Q 1 0 0 0 -o " + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("no joint or tracking point named \"Q\""), std::string::npos) << r.out;
}

TEST_F(LinkageCli, EditAndPlotWriteFiles) {
  const auto dir = testing::fresh_temp_dir();
  const std::string out = (dir / "edited.json").string();
  testing::CommandResult r = run("linkage edit " + example_path("jansen.json") + " --drag U -30 35 --keep-trajectory foot -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("motion: full rotation"), std::string::npos) << r.out;
  const Linkage edited = read_linkage(out);
  EXPECT_LT((edited.joints[edited.find_joint("U")].position - Eigen::Vector2d(-30, 35)).norm(),
            (test::example("jansen.json").joints[edited.find_joint("U")].position - Eigen::Vector2d(-30, 35)).norm());
  r = run("linkage edit " + example_path("jansen.json") + " -o " + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("nothing to edit"), std::string::npos) << r.out;
  r = run("linkage edit " + example_path("jansen.json") + " --drag Q 1 2 -o " + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("no joint or tracking point named \"Q\""), std::string::npos) << r.out;
  r = run("linkage edit " + example_path("jansen.json") + " --drag U 1 x -o " + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("\"x\" is not a number"), std::string::npos) << r.out;
  r = run("linkage edit " + example_path("jansen.json") + " --envelope 0 0 -1 5 -o " + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("min < max"), std::string::npos) << r.out;
  r = run("linkage edit " + example_path("peaucellier_lipkin.json") + " --drag P 2 0 --at 100 -o " + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("hits a singularity"), std::string::npos) << r.out;
  r = run("linkage plot " + example_path("klann.json") + " -o " + (dir / "missing-dir" / "k.svg").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("cannot open for writing"), std::string::npos) << r.out;
  r = run("linkage plot " + example_path("klann.json") + " -o " + (dir / "k.svg").string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(std::filesystem::file_size(dir / "k.svg") > 1000);
}

}  // namespace
}  // namespace reconfig::linkage
