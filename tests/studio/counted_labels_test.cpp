// Labels count in English: "1 transition", not "1 transitions"; the status bar's collision line
// says so for a design of one transition, and counts clearance intervals apart from collisions.

#include <gtest/gtest.h>

#include <fstream>

#include "counted.h"
#include "frontend.h"
#include "support/test_data.h"

namespace reconfig::studio {
namespace {

TEST(Counted, SingularForOnePluralOtherwise) {
  EXPECT_EQ(counted(0, "collision interval"), "0 collision intervals");
  EXPECT_EQ(counted(1, "collision interval"), "1 collision interval");
  EXPECT_EQ(counted(2, "transition"), "2 transitions");
}

TEST(Counted, TheStatusBarCountsOneIntervalInOneTransition) {
  // A box pushed through another: one transition, one collision interval.
  const std::filesystem::path file = testing::fresh_temp_dir() / "push.json";
  std::ofstream(file) << R"({"format": "reconfig-scene", "version": 1,
    "parts": [{"name": "wall", "box": {"size": [0.1, 1, 1]}}, {"name": "block", "box": {"size": [0.3, 0.3, 0.3]}}],
    "states": [{"name": "left", "poses": {"block": {"translation": [-1, 0, 0]}}},
               {"name": "right", "poses": {"block": {"translation": [1, 0, 0]}}}],
    "transitions": [{"name": "push", "from": "left", "to": "right", "tracks": {"block": {"translation": [
      {"time": 0, "point": [-1, 0, 0]}, {"time": 1, "point": [1, 0, 0]}]}}}]})";
  HeadlessFrontend frontend(800, 600);
  ASSERT_TRUE(frontend.studio().open(file)) << frontend.studio().status();
  ASSERT_TRUE(frontend.run_until_collisions_current(std::chrono::seconds(60)));
  EXPECT_EQ(frontend.studio().collision_summary(), "collisions: 1 interval in 1 transition, up to date");
}

TEST(Counted, TheStatusBarCountsClearanceIntervalsApart) {
  // A box sliding past a wall 0.05 away, with a clearance of 0.1: no collision, one clearance.
  const std::filesystem::path file = testing::fresh_temp_dir() / "pass.json";
  std::ofstream(file) << R"({"format": "reconfig-scene", "version": 1, "collision": {"clearance": 0.1},
    "parts": [{"name": "wall", "box": {"size": [0.1, 1, 1]}}, {"name": "block", "box": {"size": [0.3, 0.3, 0.3]}}],
    "states": [{"name": "left", "poses": {"block": {"translation": [-1, 0.7, 0]}}},
               {"name": "right", "poses": {"block": {"translation": [1, 0.7, 0]}}}],
    "transitions": [{"name": "pass", "from": "left", "to": "right", "tracks": {"block": {"translation": [
      {"time": 0, "point": [-1, 0.7, 0]}, {"time": 1, "point": [1, 0.7, 0]}]}}}]})";
  HeadlessFrontend frontend(800, 600);
  ASSERT_TRUE(frontend.studio().open(file)) << frontend.studio().status();
  ASSERT_TRUE(frontend.run_until_collisions_current(std::chrono::seconds(60)));
  EXPECT_EQ(frontend.studio().collision_summary(),
            "collisions: 0 intervals and 1 clearance interval in 1 transition, up to date");
}

}  // namespace
}  // namespace reconfig::studio
