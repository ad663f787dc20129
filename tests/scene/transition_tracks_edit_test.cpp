#include <gtest/gtest.h>

#include "reconfig/common/input_error.h"
#include "reconfig/scene/edits.h"
#include "reconfig/scene/history.h"
#include "support/random_scene.h"

namespace reconfig::scene {
namespace {

TEST(SetTransitionTracks, ReplacesSeveralTracksInOneUndoableStep) {
  Reconfigurable scene = testing::random_scene(3, {.parts = 3, .moving = 2});
  const Reconfigurable original = scene;
  const std::string a = scene.parts[0].name, b = scene.parts[1].name;
  std::map<std::string, Track> tracks = {{a, scene.transitions[0].tracks.at(a)}, {b, scene.transitions[0].tracks.at(b)}};
  auto& ta = std::get<KeyframedTrack>(tracks.at(a));
  auto& tb = std::get<KeyframedTrack>(tracks.at(b));
  ta.translation.front().out += Eigen::Vector3d(0, 0, 0.3);
  tb.translation.back().in += Eigen::Vector3d(0.2, 0, 0);
  History history;
  const DirtySet dirty = history.execute(scene, set_transition_tracks("move", tracks, "resolve move automatically"));
  ASSERT_EQ(dirty.ranges.size(), 2u);  // both parts' motion, over the whole transition
  EXPECT_EQ(dirty.ranges[0].t0, 0.0);
  EXPECT_EQ(dirty.ranges[0].t1, 1.0);
  EXPECT_EQ(history.undo_label(), "resolve move automatically");
  EXPECT_EQ(std::get<KeyframedTrack>(scene.transitions[0].tracks.at(a)).translation.front().out, ta.translation.front().out);
  history.undo(scene);
  EXPECT_EQ(std::get<KeyframedTrack>(scene.transitions[0].tracks.at(a)).translation.front().out,
            std::get<KeyframedTrack>(original.transitions[0].tracks.at(a)).translation.front().out);
  EXPECT_EQ(std::get<KeyframedTrack>(scene.transitions[0].tracks.at(b)).translation.back().in,
            std::get<KeyframedTrack>(original.transitions[0].tracks.at(b)).translation.back().in);
  history.redo(scene);
  EXPECT_EQ(std::get<KeyframedTrack>(scene.transitions[0].tracks.at(b)).translation.back().in, tb.translation.back().in);
}

TEST(SetTransitionTracks, AnInvalidResultIsRefusedAndChangesNothing) {
  Reconfigurable scene = testing::random_scene(4, {.parts = 2, .moving = 1});
  const std::string a = scene.parts[0].name;
  std::map<std::string, Track> tracks = {{a, scene.transitions[0].tracks.at(a)}};
  auto& keys = std::get<KeyframedTrack>(tracks.at(a)).translation;
  keys.back().point += Eigen::Vector3d(1, 0, 0);  // no longer the end state's pose
  const auto before = std::get<KeyframedTrack>(scene.transitions[0].tracks.at(a)).translation.back().point;
  History history;
  EXPECT_THROW(history.execute(scene, set_transition_tracks("move", tracks, "bad")), InputError);
  EXPECT_EQ(std::get<KeyframedTrack>(scene.transitions[0].tracks.at(a)).translation.back().point, before);
  EXPECT_THROW(history.execute(scene, set_transition_tracks("nope", tracks, "bad")), InputError);
}

}  // namespace
}  // namespace reconfig::scene
