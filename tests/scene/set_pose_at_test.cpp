#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "reconfig/common/input_error.h"
#include "reconfig/scene/edits.h"
#include "reconfig/scene/history.h"
#include "reconfig/scene/scene_file.h"

namespace reconfig::scene {
namespace {

Reconfigurable make_scene() {
  return parse_scene(R"({
    "format": "reconfig-scene", "version": 1,
    "parts": [{"name": "lid", "box": {"size": [1, 0.5, 0.1]}}, {"name": "post", "cylinder": {"radius": 0.1, "height": 1}}],
    "states": [
      {"name": "closed", "poses": {"lid": {"translation": [0, 0, 0.45]}}},
      {"name": "open", "poses": {"lid": {"translation": [0, 0.2, 0.75], "rotation": [0.7071068, 0.7071068, 0, 0]}}}
    ],
    "transitions": [
      {"name": "unfold", "from": "closed", "to": "open", "tracks": {"lid": {
         "translation": [
           {"time": 0.0, "point": [0, 0, 0.45], "out": [0, 0.1, 0.6]},
           {"time": 0.4, "point": [0, 0.1, 0.6], "in": [0, 0.05, 0.6], "out": [0, 0.15, 0.65]},
           {"time": 1.0, "point": [0, 0.2, 0.75], "in": [0, 0.2, 0.6]}],
         "rotation": [
           {"time": 0.0, "quaternion": [1, 0, 0, 0]},
           {"time": 1.0, "quaternion": [0.7071068, 0.7071068, 0, 0]}]},
       "post": {"interpolation": "screw", "poses": [{"time": 0, "translation": [0, 0, 0]}, {"time": 1, "translation": [0, 0, 0]}]}}}
    ]})",
                     std::filesystem::current_path(), "set_pose_at.json");
}

motion::Pose random_pose(std::mt19937& random) {
  std::uniform_real_distribution<double> u(-1, 1);
  motion::Pose pose;
  pose.translation = Eigen::Vector3d(u(random), u(random), u(random));
  pose.rotation = Eigen::Quaterniond(Eigen::Vector4d(u(random), u(random), u(random), u(random)).normalized());
  return pose;
}

void expect_pose_near(const motion::Pose& a, const motion::Pose& b) {
  EXPECT_LE((a.translation - b.translation).norm(), 1e-12);
  EXPECT_GE(std::abs(a.rotation.dot(b.rotation)), 1 - 1e-12);
}

// The hardest promise: after the edit the part is exactly where it was dragged, at inner times
// with and without existing keys, on keyframed and screw tracks, and undo restores everything.
TEST(SetPoseAt, PlacesThePartExactlyAtInnerTimesAndUndoes) {
  std::mt19937 random(7);
  for (const char* part : {"lid", "post"}) {
    for (const double t : {0.4, 0.25, 0.8}) {
      Reconfigurable scene = make_scene();
      const Reconfigurable original = scene;
      History history;
      const motion::Pose target = random_pose(random);
      const DirtySet dirty = history.execute(scene, set_pose_at(scene, "unfold", part, t, target));
      expect_pose_near(scene.pose_at(0, scene.find_part(part), t), target);
      ASSERT_EQ(dirty.ranges.size(), 1u);
      EXPECT_LT(dirty.ranges[0].t0, t);
      EXPECT_GT(dirty.ranges[0].t1, t);
      // The motion outside the dirty range is untouched.
      for (int i = 0; i <= 100; ++i) {
        const double s = i / 100.0;
        if (s > dirty.ranges[0].t0 && s < dirty.ranges[0].t1) continue;
        expect_pose_near(scene.pose_at(0, scene.find_part(part), s), original.pose_at(0, scene.find_part(part), s));
      }
      history.undo(scene);
      for (int i = 0; i <= 20; ++i)
        expect_pose_near(scene.pose_at(0, scene.find_part(part), i / 20.0),
                         original.pose_at(0, scene.find_part(part), i / 20.0));
    }
  }
}

TEST(SetPoseAt, AtTheEndsItEditsTheStatePose) {
  Reconfigurable scene = make_scene();
  History history;
  motion::Pose pose;
  pose.translation = Eigen::Vector3d(0.5, 0, 0.45);
  history.execute(scene, set_pose_at(scene, "unfold", "lid", 0.0, pose));
  EXPECT_EQ(scene.states[0].pose_of("lid").translation, pose.translation);
  expect_pose_near(scene.pose_at(0, 0, 0.0), pose);
  pose.translation.z() = 2;
  history.execute(scene, set_pose_at(scene, "unfold", "lid", 1.0, pose));
  expect_pose_near(scene.pose_at(0, 0, 1.0), pose);
}

TEST(SetPoseAt, RefusesBadArguments) {
  Reconfigurable scene = make_scene();
  History history;
  EXPECT_THROW(history.execute(scene, set_pose_at(scene, "nope", "lid", 0.5, {})), InputError);
  EXPECT_THROW(history.execute(scene, set_pose_at(scene, "unfold", "lid", 1.5, {})), InputError);
  EXPECT_THROW(history.execute(scene, set_pose_at(scene, "unfold", "ghost", 0.5, {})), InputError);
  EXPECT_FALSE(history.can_undo());
}

}  // namespace
}  // namespace reconfig::scene
