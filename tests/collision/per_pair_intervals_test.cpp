// Each collision interval names one pair of parts, as the paper's intervals do and as the
// reference check's are: two stools that slide into a bracket side by side give one interval
// per pair, not one interval of three parts whose boxes overlap.

#include <gtest/gtest.h>

#include <set>

#include "reconfig/collision/detect_collisions.h"
#include "reconfig/collision/reference_check.h"
#include "reconfig/scene/scene_file.h"

namespace reconfig::collision {
namespace {

/// Two stools side by side (overlapping each other) slide into a bracket through the same face:
/// where their surfaces cross the bracket's, the boxes of the two pairs overlap in space and time.
scene::Reconfigurable bracket_and_stools() {
  return scene::parse_scene(R"({"format": "reconfig-scene", "version": 1,
    "parts": [{"name": "bracket", "box": {"size": [0.4, 0.4, 0.4]}},
              {"name": "stool_left", "box": {"size": [0.4, 0.3, 0.3]}},
              {"name": "stool_right", "box": {"size": [0.35, 0.3, 0.25]}}],
    "states": [{"name": "apart", "poses": {"stool_left": {"translation": [-1, 0.04, 0]},
                                           "stool_right": {"translation": [-1, -0.04, 0]}}},
               {"name": "in", "poses": {"stool_left": {"translation": [-0.1, 0.04, 0]},
                                        "stool_right": {"translation": [-0.1, -0.04, 0]}}}],
    "transitions": [{"name": "push", "from": "apart", "to": "in", "tracks": {
      "stool_left": {"translation": [{"time": 0, "point": [-1, 0.04, 0]}, {"time": 1, "point": [-0.1, 0.04, 0]}]},
      "stool_right": {"translation": [{"time": 0, "point": [-1, -0.04, 0]}, {"time": 1, "point": [-0.1, -0.04, 0]}]}}}]})",
                            std::filesystem::current_path(), "stools.json");
}

std::set<std::vector<int>> pairs_of(const std::vector<CollisionInterval>& intervals) {
  std::set<std::vector<int>> pairs;
  for (const CollisionInterval& ci : intervals) {
    EXPECT_EQ(ci.parts.size(), 2u) << "an interval of " << ci.parts.size() << " parts";
    pairs.insert(ci.parts);
  }
  return pairs;
}

TEST(PerPairIntervals, EachIntervalNamesOnePairAndEveryPairIsCounted) {
  const scene::Reconfigurable scene = bracket_and_stools();
  const std::set<std::vector<int>> all = {{0, 1}, {0, 2}, {1, 2}};
  const CollisionResult engine = detect_collisions(scene);
  ASSERT_EQ(engine.transitions.size(), 1u);
  EXPECT_EQ(engine.transitions[0].intervals.size(), 3u);  // the badge's count: one per pair
  EXPECT_EQ(pairs_of(engine.transitions[0].intervals), all);
  const ReferenceCheckResult reference = reference_check(scene);
  EXPECT_EQ(pairs_of(reference.transitions[0].intervals), all);
}

}  // namespace
}  // namespace reconfig::collision
