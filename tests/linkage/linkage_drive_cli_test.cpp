// A linkage-driven scene checked by `reconfig check`, as a user would: the collision engine
// finds the links that sweep through each other (examples/linkage-walker).

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "support/run_command.h"
#include "support/test_data.h"

namespace reconfig::linkage {
namespace {

using nlohmann::json;

std::string walker() { return (testing::source_dir() / "examples" / "linkage-walker" / "scene.json").string(); }

/// The intervals `check --json` reports per transition name.
std::map<std::string, json> intervals(const std::string& out) {
  std::map<std::string, json> result;
  // The document ends with a "}" on a line of its own; ignore anything printed after it.
  const std::size_t end = out.rfind("\n}");
  const json document = json::parse(out.substr(0, end == std::string::npos ? out.size() : end + 2));
  for (const json& transition : document["transitions"]) result[transition["name"]] = transition["intervals"];
  return result;
}

void expect_collision_only_in_the_flat_walk(const testing::CommandResult& run) {
  ASSERT_EQ(run.exit_code, 1) << run.out << run.err;
  const auto found = intervals(run.out);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_TRUE(found.at("walk").empty()) << found.at("walk");
  const json& flat = found.at("walk_flat");
  ASSERT_EQ(flat.size(), 1u) << flat;
  EXPECT_EQ(flat[0]["parts"], json::array({"lower_bar", "upper_triangle"}));
  // The bar passes the triangle's corner at B while the crank turns from about 175° to 208°.
  EXPECT_NEAR(flat[0]["t0"].get<double>(), 175.5 / 360, 0.01);
  EXPECT_NEAR(flat[0]["t1"].get<double>(), 207.5 / 360, 0.01);
}

TEST(LinkageDriveCli, TheEngineFindsTheLinksThatSweepThroughEachOther) {
  expect_collision_only_in_the_flat_walk(testing::run_reconfig("check " + walker() + " --json"));
}

TEST(LinkageDriveCli, TheReferenceCheckAgrees) {
  expect_collision_only_in_the_flat_walk(testing::run_reconfig("check " + walker() + " --json --reference"));
}

TEST(LinkageDriveCli, ABrokenDriveIsBadInput) {
  json scene = json::parse(std::ifstream(walker()));
  scene["transitions"][1]["linkage"]["attach"][2]["link"] = {"C", "B"};
  const std::filesystem::path dir = testing::fresh_temp_dir();
  std::filesystem::copy(testing::source_dir() / "examples" / "linkage-walker" / "meshes", dir / "meshes");
  for (json& transition : scene["transitions"])
    transition["linkage"]["file"] = (testing::source_dir() / "examples" / "linkages" / "jansen.json").string();
  {
    std::ofstream(dir / "scene.json") << scene.dump(2);
  }
  const testing::CommandResult run = testing::run_reconfig("check " + (dir / "scene.json").string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("scene.json: transitions[1].linkage.attach[2].link: joints \"C\" and \"B\" are not two "
                         "joints of one link"),
            std::string::npos)
      << run.err;
}

}  // namespace
}  // namespace reconfig::linkage
