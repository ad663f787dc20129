#include "reconfig/scene/edits.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "reconfig/common/input_error.h"
#include "reconfig/geometry/primitives.h"
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
      {"name": "open", "poses": {"lid": {"translation": [0, 0.2, 0.75], "rotation": [0.7071068, 0.7071068, 0, 0]}}},
      {"name": "away", "poses": {"lid": {"translation": [0, 0.2, 0.75], "rotation": [0.7071068, 0.7071068, 0, 0]},
                                 "post": {"translation": [3, 0, 0]}}}
    ],
    "transitions": [
      {"name": "unfold", "from": "closed", "to": "open", "tracks": {"lid": {
         "translation": [
           {"time": 0.0, "point": [0, 0, 0.45], "out": [0, 0.1, 0.6]},
           {"time": 0.4, "point": [0, 0.1, 0.6], "in": [0, 0.05, 0.6], "out": [0, 0.15, 0.65]},
           {"time": 1.0, "point": [0, 0.2, 0.75], "in": [0, 0.2, 0.6]}],
         "rotation": [
           {"time": 0.0, "quaternion": [1, 0, 0, 0]},
           {"time": 0.5, "quaternion": [0.9238795, 0.3826834, 0, 0]},
           {"time": 1.0, "quaternion": [0.7071068, 0.7071068, 0, 0]}]}}},
      {"name": "clear", "from": "open", "to": "away", "tracks": {"post": {"interpolation": "screw", "poses": [
         {"time": 0, "translation": [0, 0, 0]}, {"time": 1, "translation": [3, 0, 0]}]}}}
    ]})",
                     std::filesystem::current_path(), "edits.json");
}

/// The whole motion of every part, sampled, to compare scenes.
std::vector<Eigen::Vector3d> motion_samples(const Reconfigurable& scene) {
  std::vector<Eigen::Vector3d> samples;
  for (int tr = 0; tr < static_cast<int>(scene.transitions.size()); ++tr)
    for (int p = 0; p < static_cast<int>(scene.parts.size()); ++p)
      for (int i = 0; i <= 50; ++i) {
        const motion::Pose pose = scene.pose_at(tr, p, i / 50.0);
        samples.push_back(pose.translation);
        samples.push_back(pose.rotation * Eigen::Vector3d(1, 2, 3));
      }
  return samples;
}

void expect_same_motion(const Reconfigurable& a, const Reconfigurable& b, double tolerance = 0) {
  const auto x = motion_samples(a), y = motion_samples(b);
  ASSERT_EQ(x.size(), y.size());
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_LE((x[i] - y[i]).norm(), tolerance) << "sample " << i;
}

TEST(Edits, MoveKeyReportsItsNeighbourhoodAndUndoes) {
  Reconfigurable scene = make_scene();
  const Reconfigurable original = make_scene();
  History history;
  const DirtySet dirty = history.execute(
      scene, set_translation_key("unfold", "lid", 1, {0.3, {0, 0.3, 0.9}, {0, 0.3, 0.8}, {0, 0.3, 1.0}}));
  ASSERT_EQ(dirty.ranges.size(), 1u);
  EXPECT_EQ(dirty.ranges[0], (DirtyRange{0, 0, 0.0, 1.0}));
  EXPECT_TRUE(scene.pose_at(0, 0, 0.3).translation.isApprox(Eigen::Vector3d(0, 0.3, 0.9)));
  // Outside the dirty range nothing moved; the other transition is untouched.
  const DirtySet undone = history.undo(scene);
  EXPECT_EQ(undone.ranges, dirty.ranges);
  expect_same_motion(scene, original);
  history.redo(scene);
  EXPECT_TRUE(scene.pose_at(0, 0, 0.3).translation.isApprox(Eigen::Vector3d(0, 0.3, 0.9)));
  EXPECT_EQ(history.undo_label(), "move translation key 1 of lid");
}

TEST(Edits, InsertingKeysKeepsTheMotion) {
  Reconfigurable scene = make_scene();
  const Reconfigurable original = make_scene();
  History history;
  for (double t : {0.1, 0.55, 0.93}) {
    const DirtySet dirty = history.execute(scene, insert_key("unfold", "lid", KeyKind::kTranslation, t));
    ASSERT_EQ(dirty.ranges.size(), 1u);
    EXPECT_LT(dirty.ranges[0].t0, t);
    EXPECT_GT(dirty.ranges[0].t1, t);
    history.execute(scene, insert_key("unfold", "lid", KeyKind::kRotation, t));
  }
  history.execute(scene, insert_key("clear", "post", KeyKind::kTranslation, 0.37));  // screw key pose
  history.execute(scene, insert_key("unfold", "post", KeyKind::kRotation, 0.5));     // creates a holding track
  expect_same_motion(scene, original, 1e-12);
  const auto& keyed = std::get<KeyframedTrack>(scene.transitions[0].tracks.at("lid"));
  EXPECT_EQ(keyed.translation.size(), 6u);
  EXPECT_EQ(keyed.rotation.size(), 6u);
  while (history.can_undo()) history.undo(scene);
  EXPECT_EQ(scene_to_json(scene, "."), scene_to_json(original, "."));
}

TEST(Edits, RemoveKeyUndoRestoresExactly) {
  Reconfigurable scene = make_scene();
  const std::string before = scene_to_json(scene, ".");
  History history;
  history.execute(scene, remove_key("unfold", "lid", KeyKind::kRotation, 1));
  EXPECT_EQ(std::get<KeyframedTrack>(scene.transitions[0].tracks.at("lid")).rotation.size(), 2u);
  history.undo(scene);
  EXPECT_EQ(scene_to_json(scene, "."), before);
}

TEST(Edits, StatePoseMovesEveryTouchingTransitionEnd) {
  Reconfigurable scene = make_scene();
  History history;
  motion::Pose pose;
  pose.translation = {0, 0.25, 0.8};
  pose.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitX()));
  const DirtySet dirty = history.execute(scene, set_state_pose("open", "lid", pose));
  // "unfold" ends in "open" (track: last stretch dirty); "clear" starts there and the lid had no
  // track, so it now gets one over the whole transition.
  EXPECT_EQ(dirty.ranges.size(), 2u);
  for (double t : {1.0}) EXPECT_TRUE(scene.pose_at(0, 0, t).translation.isApprox(pose.translation));
  EXPECT_TRUE(scene.pose_at(1, 0, 0.0).translation.isApprox(pose.translation));
  EXPECT_TRUE(scene.pose_at(1, 0, 1.0).translation.isApprox(Eigen::Vector3d(0, 0.2, 0.75)));
  history.undo(scene);
  EXPECT_EQ(scene_to_json(scene, "."), scene_to_json(make_scene(), "."));
}

TEST(Edits, InvalidEditsAreRefusedAndLeaveTheSceneUntouched) {
  Reconfigurable scene = make_scene();
  const std::string before = scene_to_json(scene, ".");
  History history;
  EXPECT_THROW(history.execute(scene, set_translation_key("unfold", "lid", 0, {0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()})), InputError);
  EXPECT_THROW(history.execute(scene, set_translation_key("unfold", "lid", 1, {1.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()})), InputError);
  EXPECT_THROW(history.execute(scene, set_rotation_key("unfold", "lid", 7, {0.5, Eigen::Quaterniond::Identity()})), InputError);
  EXPECT_THROW(history.execute(scene, insert_key("unfold", "lid", KeyKind::kRotation, 0.5)), InputError);
  EXPECT_THROW(history.execute(scene, remove_key("nope", "lid", KeyKind::kRotation, 1)), InputError);
  EXPECT_THROW(history.execute(scene, set_state_pose("closed", "ghost", {})), InputError);
  EXPECT_THROW(history.execute(scene, replace_part_mesh("lid", {})), InputError);
  EXPECT_THROW(history.execute(scene, set_collision_settings({.tolerance = -1e-3})), InputError);
  EXPECT_THROW(history.execute(scene, set_collision_settings({.dop = 12})), InputError);
  EXPECT_FALSE(history.can_undo());
  EXPECT_EQ(scene_to_json(scene, "."), before);
}

TEST(Edits, ReplaceMeshKeepsThePivotAndDirtiesEverything) {
  Reconfigurable scene = make_scene();
  const Eigen::Vector3d center = scene.parts[0].center;
  History history;
  const DirtySet dirty = history.execute(scene, replace_part_mesh("lid", geometry::make_sphere(0.3)));
  EXPECT_EQ(dirty.geometry_changed, std::vector<int>{0});
  EXPECT_EQ(dirty.ranges.size(), scene.transitions.size());
  EXPECT_EQ(scene.parts[0].center, center);
  EXPECT_TRUE(std::holds_alternative<EditedMesh>(scene.parts[0].source));
  history.undo(scene);
  EXPECT_EQ(scene.parts[0].mesh.face_count(), 12);
}

TEST(Edits, EndKeysChangeTheirHandlesButNotTheirPoints) {
  Reconfigurable scene = make_scene();
  const std::string before = scene_to_json(scene, ".");
  History history;
  const auto keys = [&] { return std::get<KeyframedTrack>(scene.transitions[0].tracks.at("lid")).translation; };
  motion::TranslationKey first = keys().front();
  first.out = {0, 0.3, 0.5};
  const DirtySet dirty = history.execute(scene, set_translation_key("unfold", "lid", 0, first));
  ASSERT_EQ(dirty.ranges.size(), 1u);
  EXPECT_EQ(dirty.ranges[0].t0, 0.0);  // the first segment, up to the next key
  EXPECT_EQ(dirty.ranges[0].t1, 0.4);
  EXPECT_EQ(keys().front().out, first.out);
  EXPECT_TRUE(scene.pose_at(0, 0, 0.0).translation.isApprox(Eigen::Vector3d(0, 0, 0.45)));  // still the state's

  motion::TranslationKey last = keys().back();
  last.in = {0, 0.25, 0.7};
  EXPECT_EQ(history.execute(scene, set_translation_key("unfold", "lid", 2, last)).ranges[0].t0, 0.4);
  EXPECT_EQ(keys().back().in, last.in);

  // Moving an end key's point, or its time, is still refused.
  last.point.z() += 0.1;
  EXPECT_THROW(history.execute(scene, set_translation_key("unfold", "lid", 2, last)), InputError);
  first.time = 0.1;
  EXPECT_THROW(history.execute(scene, set_translation_key("unfold", "lid", 0, first)), InputError);
  history.undo(scene);
  history.undo(scene);
  EXPECT_EQ(scene_to_json(scene, "."), before);
}

TEST(Edits, CollisionSettingsAreSavedUndoneAndRedone) {
  Reconfigurable scene = make_scene();
  History history;
  const CollisionSettings first{.tolerance = 2e-3, .dop = 8}, second{.box_resolution = 0.0, .conservative = true};
  const DirtySet dirty = history.execute(scene, set_collision_settings(first));
  EXPECT_TRUE(dirty.structure_changed);  // every transition is detected again
  EXPECT_EQ(scene.collision, first);
  history.execute(scene, set_collision_settings(second));
  EXPECT_EQ(scene.collision, second);
  EXPECT_TRUE(history.undo(scene).structure_changed);
  EXPECT_EQ(scene.collision, first);
  history.undo(scene);
  EXPECT_TRUE(scene.collision.empty());
  history.redo(scene);
  EXPECT_EQ(scene.collision, first);
}

/// Random sequences of edits, undone one by one, give back the original exactly; redone, they
/// give back the edited scene exactly.
TEST(Edits, RandomEditSequencesUndoAndRedoExactly) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int round = 0; round < 20; ++round) {
    Reconfigurable scene = make_scene();
    const std::string original = scene_to_json(scene, ".");
    History history;
    for (int step = 0; step < 12; ++step) {
      try {
        switch (random() % 4) {
          case 0: history.execute(scene, insert_key("unfold", "lid", KeyKind(random() % 2), unit(random))); break;
          case 1: history.execute(scene, remove_key("unfold", "lid", KeyKind(random() % 2), 1)); break;
          case 2: {
            motion::Pose pose;
            pose.translation = Eigen::Vector3d::Random();
            history.execute(scene, set_state_pose(random() % 2 ? "open" : "closed", "lid", pose));
            break;
          }
          default:
            history.execute(scene, set_rotation_key("unfold", "lid", 1,
                                                    {0.2 + 0.6 * unit(random), Eigen::Quaterniond::UnitRandom()}));
        }
      } catch (const InputError&) {  // refused edits are fine; they must not change anything
      }
    }
    const std::string edited = scene_to_json(scene, ".");
    while (history.can_undo()) history.undo(scene);
    EXPECT_EQ(scene_to_json(scene, "."), original);
    while (history.can_redo()) history.redo(scene);
    EXPECT_EQ(scene_to_json(scene, "."), edited);
  }
}

}  // namespace
}  // namespace reconfig::scene
