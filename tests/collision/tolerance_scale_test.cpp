#include "reconfig/collision/tolerance_scale.h"

#include <gtest/gtest.h>

#include <chrono>

#include "reconfig/collision/detect_collisions.h"
#include "reconfig/common/input_error.h"
#include "reconfig/scene/scene_file.h"

namespace reconfig::collision {
namespace {

/// A beam of length `length` that turns a quarter turn about z next to a post.
scene::Reconfigurable turning_beam(double length) {
  const std::string size = std::to_string(length);
  return scene::parse_scene(R"({"format": "reconfig-scene", "version": 1, "units": "m",
    "parts": [{"name": "beam", "box": {"size": [)" + size + R"(, 0.05, 0.5]}},
              {"name": "post", "box": {"size": [0.1, 0.1, 1]}}],
    "states": [{"name": "a", "poses": {"post": {"translation": [0, 1, 0]}}},
               {"name": "b", "poses": {"post": {"translation": [0, 1, 0]},
                                       "beam": {"rotation": [0.70710678118654757, 0, 0, 0.70710678118654757]}}}],
    "transitions": [{"name": "turn", "from": "a", "to": "b", "tracks": {"beam": {"rotation": [
      {"time": 0, "quaternion": [1, 0, 0, 0]},
      {"time": 1, "quaternion": [0.70710678118654757, 0, 0, 0.70710678118654757]}]}}}]})",
                             ".", "beam.json");
}

TEST(ToleranceScale, ATolerancePracticalForTheDesignIsFine) {
  EXPECT_EQ(tolerance_scale_problem(turning_beam(2), {}, 1e-3), "");
  EXPECT_EQ(tolerance_scale_problem(turning_beam(1e5), {0}, 1e-3), "");  // 5e7 times: under a second
}

TEST(ToleranceScale, AnAbsurdRatioIsRefusedAtOnceNotMinutesLater) {
  const scene::Reconfigurable huge = turning_beam(1e7);  // 34 s and 0.9 GB before
  const std::string problem = tolerance_scale_problem(huge, {}, 1e-3);
  EXPECT_NE(problem.find("too fine for part \"beam\", which reaches 5e+06 from its center"), std::string::npos)
      << problem;
  EXPECT_NE(problem.find("use a tolerance of at least 0.05"), std::string::npos) << problem;
  const auto start = std::chrono::steady_clock::now();
  try {
    detect_collisions(huge);
    FAIL() << "detected at a tolerance of 1e-3 on a part 1e7 long";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "collision.tolerance");
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
  CollisionRequest coarse;
  coarse.detector.tolerance = 1;
  EXPECT_NO_THROW(detect_collisions(huge, coarse));
}

TEST(ToleranceScale, PartsThatHoldStillDoNotCount) {
  scene::Reconfigurable still = turning_beam(1e7);
  still.transitions[0].tracks.clear();
  still.states[1].poses.erase("beam");
  EXPECT_EQ(tolerance_scale_problem(still, {}, 1e-3), "");
}

}  // namespace
}  // namespace reconfig::collision
