#include <gtest/gtest.h>

#include "reconfig/common/input_error.h"
#include "reconfig/scene/edits.h"
#include "reconfig/scene/history.h"
#include "support/random_scene.h"

namespace reconfig::scene {
namespace {

motion::Pose moved_by(motion::Pose pose, const Eigen::Vector3d& shift) {
  pose.translation += shift;
  return pose;
}

TEST(CommandSequence, AppliesItsStepsAsOneUndoableStep) {
  Reconfigurable scene = testing::random_scene(5, {.parts = 2, .moving = 2});
  const Reconfigurable original = scene;
  const std::string a = scene.parts[0].name, b = scene.parts[1].name;
  const motion::Pose pa = moved_by(scene.states[0].pose_of(a), {0.1, 0, 0});
  const motion::Pose pb = moved_by(scene.states[1].pose_of(b), {0, 0.2, 0});
  std::vector<std::unique_ptr<Command>> steps;
  steps.push_back(set_state_pose(scene.states[0].name, a, pa));
  steps.push_back(set_state_pose(scene.states[1].name, b, pb));
  History history;
  const DirtySet dirty = history.execute(scene, command_sequence("move two states", std::move(steps)));
  EXPECT_EQ(dirty.ranges.size(), 2u);  // both parts, one end each
  EXPECT_EQ(history.undo_label(), "move two states");
  EXPECT_EQ(scene.states[0].pose_of(a).translation, pa.translation);
  EXPECT_EQ(scene.states[1].pose_of(b).translation, pb.translation);
  EXPECT_EQ(scene.pose_at(0, 0, 0.0).translation, pa.translation);
  history.undo(scene);  // both at once
  EXPECT_EQ(scene.states[0].pose_of(a).translation, original.states[0].pose_of(a).translation);
  EXPECT_EQ(scene.states[1].pose_of(b).translation, original.states[1].pose_of(b).translation);
  EXPECT_EQ(scene.pose_at(0, 0, 0.0).translation, original.pose_at(0, 0, 0.0).translation);
  EXPECT_FALSE(history.can_undo());
}

TEST(CommandSequence, ARefusedStepUndoesTheOnesBeforeIt) {
  Reconfigurable scene = testing::random_scene(6, {.parts = 2, .moving = 1});
  const Reconfigurable original = scene;
  const std::string a = scene.parts[0].name;
  std::vector<std::unique_ptr<Command>> steps;
  steps.push_back(set_state_pose(scene.states[0].name, a, moved_by(scene.states[0].pose_of(a), {0.3, 0, 0})));
  steps.push_back(set_state_pose("no such state", a, scene.states[0].pose_of(a)));
  auto sequence = command_sequence("half of it", std::move(steps));
  EXPECT_THROW(sequence->apply(scene), InputError);
  EXPECT_EQ(scene.states[0].pose_of(a).translation, original.states[0].pose_of(a).translation);
  EXPECT_EQ(scene.pose_at(0, 0, 0.0).translation, original.pose_at(0, 0, 0.0).translation);
}

}  // namespace
}  // namespace reconfig::scene
