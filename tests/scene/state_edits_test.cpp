#include "reconfig/scene/state_edits.h"

#include <gtest/gtest.h>

#include "edit_checks.h"
#include "reconfig/scene/transition_edits.h"
#include "support/random_scene.h"

namespace reconfig::scene {
namespace {

TEST(AddState, CopiesThePosesShownAndDirtiesNothing) {
  Reconfigurable scene = testing::random_scene(11, {.parts = 3, .moving = 2});
  const auto poses = current_poses(scene, 0, -1, 0.5);
  ASSERT_EQ(poses.size(), 3u);
  EXPECT_EQ(poses.at(scene.parts[0].name).translation, scene.pose_at(0, 0, 0.5).translation);
  const auto [dirty, edited] = round_trip(scene, add_state("halfway", poses));
  EXPECT_TRUE(dirty.empty());
  ASSERT_EQ(edited.states.size(), 3u);
  EXPECT_EQ(edited.states[2].pose_of(scene.parts[1].name).translation, scene.pose_at(0, 1, 0.5).translation);
  const auto in_state = current_poses(scene, -1, 1, 0);
  EXPECT_EQ(in_state.at(scene.parts[0].name).translation, scene.states[1].pose_of(scene.parts[0].name).translation);
}

TEST(AddState, RefusesBadInput) {
  Reconfigurable scene = testing::random_scene(12, {.parts = 2, .moving = 1});
  expect_refused(scene, add_state("start", {}), "already a state named \"start\"");
  expect_refused(scene, add_state("", {}), "needs a name");
  expect_refused(scene, add_state("other", {{"nobody", motion::Pose{}}}), "unknown part \"nobody\"");
}

TEST(RenameState, RenamesTheEndsOfItsTransitions) {
  Reconfigurable scene = testing::random_scene(13, {.parts = 2, .moving = 1});
  const auto [dirty, edited] = round_trip(scene, rename_state("start", "open"));
  EXPECT_TRUE(dirty.empty());
  EXPECT_EQ(edited.states[0].name, "open");
  EXPECT_EQ(edited.transitions[0].from, "open");
  expect_refused(scene, rename_state("start", "end"), "already a state named");
  expect_refused(scene, rename_state("middle", "x"), "unknown state \"middle\"");
}

TEST(DeleteState, IsRefusedWhileATransitionUsesIt) {
  Reconfigurable scene = testing::random_scene(14, {.parts = 2, .moving = 1});
  expect_refused(scene, delete_state("end"), "end of transition \"move\"");
  const auto [dirty, edited] = round_trip(scene, delete_state("end", true));
  EXPECT_TRUE(dirty.structure_changed);
  EXPECT_EQ(edited.states.size(), 1u);
  EXPECT_TRUE(edited.transitions.empty());
  expect_refused(scene, delete_state("middle"), "unknown state");
  History history;
  history.execute(scene, delete_state("end", true));
  expect_refused(scene, delete_state("start"), "only state");
}

TEST(DeleteState, AnUnusedStateGoesWithoutDirtying) {
  Reconfigurable scene = testing::random_scene(15, {.parts = 2, .moving = 1});
  History history;
  history.execute(scene, add_state("spare", current_poses(scene, -1, 0, 0)));
  const auto [dirty, edited] = round_trip(scene, delete_state("spare"));
  EXPECT_TRUE(dirty.empty());
  EXPECT_EQ(edited.states.size(), 2u);
}

}  // namespace
}  // namespace reconfig::scene
