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

/// The pairs of parts of every interval of `transition` in a `check --json` result, "a×b" with a < b.
std::set<std::string> colliding_pairs(const nlohmann::json& result, const std::string& transition) {
  std::set<std::string> pairs;
  for (const auto& t : result["transitions"])
    if (t["name"] == transition)
      for (const auto& ci : t["intervals"]) {
        std::string a = ci["parts"][0], b = ci["parts"][1];
        if (b < a) std::swap(a, b);
        pairs.insert(a + "×" + b);
      }
  return pairs;
}

class KitchenExample : public ::testing::TestWithParam<const char*> {};  // engine or reference

TEST_P(KitchenExample, HastyChoreographiesCollideCarefulOnesAreFree) {
  const auto run = run_reconfig("check " + kitchen() + " --json " + GetParam());
  ASSERT_EQ(run.exit_code, 1) << run.err;  // collisions found
  const nlohmann::json result = nlohmann::json::parse(run.out);
  ASSERT_EQ(result["transitions"].size(), 4u);
  // The shelf and the bin slide out through their doors while those are still opening.
  EXPECT_EQ(colliding_pairs(result, "open_hasty"),
            (std::set<std::string>{"cabinet_door_left×pullout_shelf", "cabinet_door_right×pullout_bin"}));
  // The bracket swings out through the stools stored under the table.
  EXPECT_EQ(colliding_pairs(result, "dining_hasty"),
            (std::set<std::string>{"stool_left×table_bracket", "stool_right×table_bracket"}));
  EXPECT_TRUE(colliding_pairs(result, "open").empty());
  EXPECT_TRUE(colliding_pairs(result, "dining").empty());
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
