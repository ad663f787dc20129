#include "reconfig/scene/transition_edits.h"

#include <gtest/gtest.h>

#include "edit_checks.h"
#include "reconfig/scene/state_edits.h"
#include "reconfig/scene/validate_scene.h"
#include "support/random_scene.h"

namespace reconfig::scene {
namespace {

/// The design with a third state "up" where part 0 is lifted and turned.
Reconfigurable with_lifted_state(std::uint32_t seed) {
  Reconfigurable scene = testing::random_scene(seed, {.parts = 3, .moving = 2});
  auto poses = current_poses(scene, -1, 1, 0);
  motion::Pose& lifted = poses.at(scene.parts[0].name);
  lifted.translation += Eigen::Vector3d(0, 0, 0.5);
  lifted.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitX())) * lifted.rotation;
  History history;
  history.execute(scene, add_state("up", poses));
  return scene;
}

TEST(AddTransition, MovesTheDifferingPartsOnStraightPaths) {
  Reconfigurable scene = with_lifted_state(21);
  const auto [dirty, edited] = round_trip(scene, add_transition("lift", "end", "up"));
  EXPECT_FALSE(dirty.structure_changed);  // only the new transition needs detecting
  EXPECT_EQ(dirty.added_transitions, std::vector<int>{1});
  const int lift = edited.find_transition("lift");
  ASSERT_EQ(edited.transitions[lift].tracks.size(), 1u);  // only part 0 moves
  const motion::Pose a = edited.states[1].pose_of(scene.parts[0].name), b = edited.states[2].pose_of(scene.parts[0].name);
  // Oracle: the straight line at constant speed, the slerp in between.
  for (double t : {0.0, 0.25, 0.5, 0.9, 1.0}) {
    const motion::Pose pose = edited.pose_at(lift, 0, t);
    EXPECT_TRUE(pose.translation.isApprox(a.translation + t * (b.translation - a.translation), 1e-12)) << t;
    EXPECT_LT(pose.rotation.angularDistance(a.rotation.slerp(t, b.rotation)), 1e-9) << t;
  }
  EXPECT_NO_THROW(validate_scene(edited));
}

TEST(AddTransition, ScrewChoreographyIsOneScrewMotion) {
  Reconfigurable scene = with_lifted_state(22);
  const auto [dirty, edited] = round_trip(scene, add_transition("lift", "end", "up", Choreography::kScrew));
  const Track& track = edited.transitions.back().tracks.at(scene.parts[0].name);
  ASSERT_TRUE(std::holds_alternative<ScrewPosesTrack>(track));
  EXPECT_EQ(std::get<ScrewPosesTrack>(track).poses.size(), 2u);
  // A screw motion turns at constant speed: the angle to the start grows linearly.
  const motion::Pose a = edited.pose_at(1, 0, 0), b = edited.pose_at(1, 0, 1);
  const double total = a.rotation.angularDistance(b.rotation);
  for (double t : {0.25, 0.5, 0.75})
    EXPECT_NEAR(a.rotation.angularDistance(edited.pose_at(1, 0, t).rotation), t * total, 1e-9);
}

TEST(AddTransition, RefusesBadInput) {
  Reconfigurable scene = with_lifted_state(23);
  expect_refused(scene, add_transition("move", "end", "up"), "already a transition named \"move\"");
  expect_refused(scene, add_transition("lift", "end", "nowhere"), "unknown state \"nowhere\"");
  expect_refused(scene, add_transition("", "end", "up"), "needs a name");
}

TEST(RenameTransition, DirtiesNothing) {
  Reconfigurable scene = testing::random_scene(24, {.parts = 2, .moving = 1});
  const auto [dirty, edited] = round_trip(scene, rename_transition("move", "swing"));
  EXPECT_TRUE(dirty.empty());
  EXPECT_EQ(edited.transitions[0].name, "swing");
  expect_refused(scene, rename_transition("nope", "x"), "unknown transition \"nope\"");
}

TEST(DeleteTransition, RemovesItAndUndoPutsItBack) {
  Reconfigurable scene = testing::random_scene(25, {.parts = 2, .moving = 1});
  const auto [dirty, edited] = round_trip(scene, delete_transition("move"));
  EXPECT_TRUE(dirty.structure_changed);
  EXPECT_TRUE(edited.transitions.empty());
  expect_refused(scene, delete_transition("nope"), "unknown transition");
}

TEST(ReverseTransition, PlaysTheSameMotionBackwards) {
  Reconfigurable scene = testing::random_scene(26, {.parts = 3, .moving = 2});
  const auto [dirty, edited] = round_trip(scene, reverse_transition("move"));
  EXPECT_EQ(dirty.ranges.size(), 2u);  // each moving part, over the whole transition
  EXPECT_FALSE(dirty.structure_changed);
  EXPECT_EQ(edited.transitions[0].from, "end");
  EXPECT_EQ(edited.transitions[0].to, "start");
  for (int part = 0; part < 3; ++part)
    for (double t : {0.0, 0.1, 0.33, 0.5, 0.8, 1.0}) {
      const motion::Pose forward = scene.pose_at(0, part, t), backward = edited.pose_at(0, part, 1 - t);
      EXPECT_TRUE(forward.translation.isApprox(backward.translation, 1e-9) ||
                  (forward.translation - backward.translation).norm() < 1e-12)
          << part << " " << t;
      EXPECT_LT(forward.rotation.angularDistance(backward.rotation), 1e-9) << part << " " << t;
    }
  expect_refused(scene, reverse_transition("nope"), "unknown transition");
}

TEST(DuplicateTransition, CopiesItUnderANewName) {
  Reconfigurable scene = testing::random_scene(27, {.parts = 2, .moving = 1});
  const auto [dirty, edited] = round_trip(scene, duplicate_transition("move", "move_lifted"));
  EXPECT_EQ(dirty.added_transitions, std::vector<int>{1});
  ASSERT_EQ(edited.transitions.size(), 2u);
  EXPECT_EQ(edited.transitions[1].name, "move_lifted");
  EXPECT_EQ(edited.pose_at(1, 0, 0.4).translation, edited.pose_at(0, 0, 0.4).translation);
  expect_refused(scene, duplicate_transition("move", "move"), "already a transition named");
}

}  // namespace
}  // namespace reconfig::scene
