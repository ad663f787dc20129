// The kitchen example (examples/kitchen): 22 parts; each careless choreography collides where
// its README says, each careful one is collision-free — by the engine and by the reference check.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>

#include "support/run_command.h"
#include "support/test_data.h"

namespace reconfig {
namespace {

using testing::run_reconfig;

std::string kitchen() { return (testing::source_dir() / "examples" / "kitchen" / "scene.json").string(); }

/// The parts of every interval of `transition` in a `check --json` result, each interval's
/// joined by "×" in name order (an interval where several parts meet names them all).
std::set<std::string> colliding_parts(const nlohmann::json& result, const std::string& transition) {
  std::set<std::string> found;
  for (const auto& t : result["transitions"])
    if (t["name"] == transition)
      for (const auto& ci : t["intervals"]) {
        std::vector<std::string> parts = ci["parts"];
        std::sort(parts.begin(), parts.end());
        std::string joined;
        for (const std::string& part : parts) joined += (joined.empty() ? "" : "×") + part;
        found.insert(joined);
      }
  return found;
}

class KitchenExample : public ::testing::TestWithParam<const char*> {};  // engine or reference

TEST_P(KitchenExample, HastyChoreographiesCollideCarefulOnesAreFree) {
  const auto run = run_reconfig("check " + kitchen() + " --json " + GetParam());
  ASSERT_EQ(run.exit_code, 1) << run.err;  // collisions found
  const nlohmann::json result = nlohmann::json::parse(run.out);
  ASSERT_EQ(result["transitions"].size(), 4u);
  // The shelf and the bin slide out through their doors while those are still opening.
  EXPECT_EQ(colliding_parts(result, "open_hasty"),
            (std::set<std::string>{"cabinet_door_left×pullout_shelf", "cabinet_door_right×pullout_bin"}));
  // The bracket swings out through the stools stored under the table: it is in every
  // interval, and hits both stools (near both at once, the engine reports one interval for
  // the three parts: intervals merge where they meet).
  const std::set<std::string> dining = colliding_parts(result, "dining_hasty");
  ASSERT_FALSE(dining.empty());
  std::string all;
  for (const std::string& parts : dining) {
    EXPECT_NE(parts.find("table_bracket"), std::string::npos) << parts;
    all += parts + " ";
  }
  EXPECT_NE(all.find("stool_left"), std::string::npos) << all;
  EXPECT_NE(all.find("stool_right"), std::string::npos) << all;
  EXPECT_TRUE(colliding_parts(result, "open").empty());
  EXPECT_TRUE(colliding_parts(result, "dining").empty());
  for (const auto& t : result["transitions"])
    for (const auto& ci : t["intervals"]) {
      // Both end states are fine: the collisions happen during the motion.
      EXPECT_GT(ci["t0"].get<double>(), 0.0);
      EXPECT_LT(ci["t1"].get<double>(), 0.6);
    }
}

TEST_P(KitchenExample, CarefulChoreographiesExitZero) {
  const auto run =
      run_reconfig("check " + kitchen() + " --transition open --transition dining " + GetParam());
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("transition \"open\" (closed → open): collision-free"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("transition \"dining\" (closed → dining): collision-free"), std::string::npos) << run.out;
}

INSTANTIATE_TEST_SUITE_P(EngineAndReference, KitchenExample, ::testing::Values("", "--reference --samples 400"),
                         [](const ::testing::TestParamInfo<const char*>& which) { return which.index == 0 ? "Engine" : "Reference"; });

TEST(KitchenExampleFile, HasMoreThanTwentyParts) {
  const auto run = run_reconfig("info " + kitchen() + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_GE(nlohmann::json::parse(run.out)["parts"].size(), 20u);
}

TEST(KitchenExampleFile, ConservativeModeFindsNoNearMissInTheCarefulChoreographies) {
  // The careful choreographies keep every clearance ≥ 2 mm, above the 1 mm tolerance.
  const auto run = run_reconfig("check " + kitchen() + " --conservative --transition open --transition dining");
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
}

}  // namespace
}  // namespace reconfig
