// The studio driven headless: simulated mouse and keys through ImGui, pixels through EGL.

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "keys.h"
#include "reconfig/scene/scene_file.h"
#include "script.h"
#include "studio_test_util.h"

namespace reconfig::studio {
namespace {

using std::chrono::milliseconds;

class StudioHeadless : public ::testing::Test {
 protected:
  void SetUp() override {
    scene_file_ = bench_table_copy();
    StudioOptions options;
    options.autosave_interval = milliseconds(0);
    frontend_ = std::make_unique<HeadlessFrontend>(1000, 700, options);
    ASSERT_TRUE(studio().open(scene_file_)) << studio().status();
    frontend_->run_frame();
    ASSERT_TRUE(frontend_->run_until_collisions_current(milliseconds(60000)));
  }

  Studio& studio() { return frontend_->studio(); }
  SimulatedInput& input() { return frontend_->input(); }

  void click(ImVec2 at) {
    input().mouse = at;
    frontend_->run_frame();
    input().buttons[0] = true;
    frontend_->run_frame();
    input().buttons[0] = false;
    frontend_->run_frame();
    frontend_->run_frame();  // the 3D image is drawn before the UI handles the click
  }

  void press(int key, bool ctrl = false, bool shift = false) {
    input().ctrl = ctrl;
    input().shift = shift;
    input().keys_down.insert(key);
    frontend_->run_frame();
    input().keys_down.clear();
    input().ctrl = input().shift = false;
    frontend_->run_frame();
  }

  const collision::TransitionSnapshot& shown(int transition) {
    snapshot_ = studio().collisions();
    for (const auto& t : snapshot_->transitions)
      if (t.transition == transition) return t;
    throw std::runtime_error("no such transition in the snapshot");
  }

  const scene::KeyframedTrack& track(const std::string& part) {
    const auto& scene = studio().document()->scene();
    return std::get<scene::KeyframedTrack>(scene.transitions[studio().active_transition()].tracks.at(part));
  }

  std::filesystem::path scene_file_;
  std::unique_ptr<HeadlessFrontend> frontend_;
  std::shared_ptr<const collision::CollisionSnapshot> snapshot_;
};

// The hardest case of the issue, end to end through the UI: open the free choreography, move
// an armrest with the gizmo at mid-transition, see the new collision in the timeline, undo it.
TEST_F(StudioHeadless, GizmoEditMakesACollisionAppearAndUndoRemovesIt) {
  const auto& scene = studio().document()->scene();
  const int lifted = scene.find_transition("unfold_lifted");
  click(*studio().graph_edge_point(lifted));
  ASSERT_EQ(studio().active_transition(), lifted);
  EXPECT_TRUE(shown(lifted).intervals.empty());

  click(studio().timeline_point(0.5));
  EXPECT_NEAR(studio().time(), 0.5, 0.01);
  const int armrest = scene.find_part("armrest_left");
  const auto on_armrest = visible_point(studio(), armrest);
  ASSERT_TRUE(on_armrest);
  click(*on_armrest);
  ASSERT_EQ(studio().selected_part(), armrest);
  const motion::Pose before = *studio().selected_pose();

  // Drag the z arrow up by 0.35 m.
  const Gizmo gizmo = *studio().gizmo();
  const Eigen::Vector3d from = gizmo.center + 0.7 * gizmo.arrow_length * Eigen::Vector3d::UnitZ();
  input().mouse = *studio().viewport_point(from);
  frontend_->run_frame();
  input().buttons[0] = true;
  frontend_->run_frame();
  for (int i = 1; i <= 8; ++i) {
    input().mouse = *studio().viewport_point(from + Eigen::Vector3d(0, 0, 0.35 * i / 8));
    frontend_->run_frame();
  }
  input().buttons[0] = false;
  frontend_->run_frame();
  const motion::Pose after = *studio().selected_pose();
  EXPECT_NEAR(after.translation.z() - before.translation.z(), 0.35, 0.01);
  EXPECT_NEAR((after.translation - before.translation).head<2>().norm(), 0, 1e-9);
  EXPECT_TRUE(studio().document()->modified());

  ASSERT_TRUE(frontend_->run_until_collisions_current(milliseconds(60000)));
  ASSERT_EQ(shown(lifted).intervals.size(), 1u);
  const auto& interval = shown(lifted).intervals[0];
  EXPECT_LT(interval.t0, 0.5);
  EXPECT_GT(interval.t1, 0.5);
  // The band is drawn red in the timeline (beside the playhead at 0.5).
  frontend_->run_frame();
  const render::Image image = frontend_->screenshot();
  EXPECT_TRUE(reddish(image.pixel(static_cast<int>(studio().timeline_point(0.5).x) + 6,
                                  static_cast<int>(studio().layout().bands_row_y))));

  press(keys::kZ, true);
  ASSERT_TRUE(frontend_->run_until_collisions_current(milliseconds(60000)));
  EXPECT_TRUE(shown(lifted).intervals.empty());
  EXPECT_NEAR(studio().selected_pose()->translation.z(), before.translation.z(), 1e-12);
  press(keys::kZ, true, true);
  ASSERT_TRUE(frontend_->run_until_collisions_current(milliseconds(60000)));
  EXPECT_EQ(shown(lifted).intervals.size(), 1u);
}

TEST_F(StudioHeadless, TimelineShowsBandsAndClickingOneJumpsToItsStart) {
  const int unfold = studio().active_transition();
  ASSERT_EQ(unfold, studio().document()->scene().find_transition("unfold"));
  const auto& intervals = shown(unfold).intervals;
  ASSERT_EQ(intervals.size(), 2u);  // backrest × each armrest
  frontend_->run_frame();
  const render::Image image = frontend_->screenshot();
  const int y = static_cast<int>(studio().layout().bands_row_y);
  EXPECT_TRUE(reddish(image.pixel(static_cast<int>(studio().timeline_point(0.4).x), y)));
  EXPECT_FALSE(reddish(image.pixel(static_cast<int>(studio().timeline_point(0.9).x), y)));
  EXPECT_FALSE(reddish(image.pixel(static_cast<int>(studio().timeline_point(0.05).x), y)));

  click({studio().timeline_point(0.4).x, studio().layout().bands_row_y});
  EXPECT_NEAR(studio().time(), intervals[0].t0, 1e-12);
}

TEST_F(StudioHeadless, ViewportShowsCollisionBoxesSelectionAndGhosts) {
  const auto& scene = studio().document()->scene();
  const int unfold = studio().active_transition();
  studio().set_time(0.4);
  frontend_->run_frame();
  // A collision box at t = 0.4: its center turns red when boxes are shown.
  Eigen::AlignedBox3d box;
  for (const auto& frame : shown(unfold).frames)
    if (frame.t0 <= 0.4 && 0.4 <= frame.t1) box = frame.box;
  ASSERT_FALSE(box.isEmpty());
  const ImVec2 at = *studio().viewport_point(box.center());
  const auto with_boxes = frontend_->screenshot().pixel(static_cast<int>(at.x), static_cast<int>(at.y));
  studio().show_intervals = false;
  frontend_->run_frame();
  const auto without_boxes = frontend_->screenshot().pixel(static_cast<int>(at.x), static_cast<int>(at.y));
  EXPECT_GT(color_distance(with_boxes, without_boxes), 40);
  EXPECT_GT(with_boxes[0] - with_boxes[2], without_boxes[0] - without_boxes[2]);

  // Selecting the backrest (a click on it) tints it.
  const int backrest = scene.find_part("backrest");
  const auto backrest_point = visible_point(studio(), backrest);
  ASSERT_TRUE(backrest_point);
  const int x = static_cast<int>(backrest_point->x), y = static_cast<int>(backrest_point->y);
  const auto plain = frontend_->screenshot().pixel(x, y);
  click(*backrest_point);
  ASSERT_EQ(studio().selected_part(), backrest);
  const auto selected = frontend_->screenshot().pixel(x, y);
  EXPECT_GT(color_distance(plain, selected), 20);

  // Ghosts of the moving parts change a good share of the viewport once they show.
  studio().select_part(-1);
  studio().set_time(0.7);
  studio().show_ghosts = true;
  frontend_->run_frame();
  const render::Image ghosted = frontend_->screenshot();
  studio().show_ghosts = false;
  frontend_->run_frame();
  const render::Image unghosted = frontend_->screenshot();
  int changed = 0;
  const Layout& layout = studio().layout();
  for (int py = static_cast<int>(layout.viewport_min.y); py < static_cast<int>(layout.viewport_max.y); ++py)
    for (int px = static_cast<int>(layout.viewport_min.x); px < static_cast<int>(layout.viewport_max.x); ++px)
      changed += color_distance(ghosted.pixel(px, py), unghosted.pixel(px, py)) > 15;
  EXPECT_GT(changed, 2000);
}

TEST_F(StudioHeadless, KeysInsertSelectDragDeleteUndoAndRedo) {
  const auto& scene = [&]() -> const scene::Reconfigurable& { return studio().document()->scene(); };
  studio().select_part(scene().find_part("backrest"));
  const std::size_t keys = track("backrest").translation.size();
  studio().set_time(0.3);
  press('I');
  ASSERT_EQ(track("backrest").translation.size(), keys + 1);
  int inserted = -1;
  for (std::size_t i = 0; i < track("backrest").translation.size(); ++i)
    if (track("backrest").translation[i].time == 0.3) inserted = static_cast<int>(i);
  ASSERT_GE(inserted, 0);

  // Click the diamond to select it, then drag it to t = 0.25.
  const float y = studio().layout().translation_row_y;
  click({studio().timeline_point(0.3).x, y});
  ASSERT_TRUE(studio().selected_key());
  EXPECT_EQ(studio().selected_key()->index, inserted);
  input().mouse = {studio().timeline_point(0.3).x, y};
  frontend_->run_frame();
  input().buttons[0] = true;
  frontend_->run_frame();
  for (int i = 1; i <= 5; ++i) {
    input().mouse = {studio().timeline_point(0.3 - 0.05 * i / 5).x, y};
    frontend_->run_frame();
  }
  input().buttons[0] = false;
  frontend_->run_frame();
  EXPECT_NEAR(track("backrest").translation[inserted].time, 0.25, 0.005);

  press(keys::kDelete);
  EXPECT_EQ(track("backrest").translation.size(), keys);
  press(keys::kZ, true);
  EXPECT_EQ(track("backrest").translation.size(), keys + 1);
  press(keys::kZ, true, true);
  EXPECT_EQ(track("backrest").translation.size(), keys);
}

TEST_F(StudioHeadless, SpacePlaysAndArrowsStep) {
  studio().set_time(0);
  press(keys::kSpace);
  EXPECT_TRUE(studio().playing());
  for (int i = 0; i < 30; ++i) frontend_->run_frame();
  EXPECT_GT(studio().time(), 0.05);
  press(keys::kSpace);
  EXPECT_FALSE(studio().playing());
  const double t = studio().time();
  press(keys::kRight);
  EXPECT_NEAR(studio().time(), t + 0.01, 1e-12);
  press(keys::kLeft);
  press(keys::kLeft);
  EXPECT_NEAR(studio().time(), t - 0.01, 1e-12);
}

TEST_F(StudioHeadless, EditsAutosaveAndTheAutosaveRecoversThem) {
  studio().select_part(studio().document()->scene().find_part("seat"));
  studio().set_time(0.5);
  motion::Pose pose = *studio().selected_pose();
  pose.translation.x() += 0.1;
  ASSERT_TRUE(studio().apply_pose(pose));
  frontend_->run_frame();
  EXPECT_TRUE(Document::has_recovery(scene_file_));
  const auto recovered = Document::recover(scene_file_);
  EXPECT_TRUE(recovered->modified());
  EXPECT_NEAR(recovered->scene().pose_at(0, recovered->scene().find_part("seat"), 0.5).translation.x(),
              pose.translation.x(), 1e-9);

  // Saving writes the file atomically and drops the autosave.
  ASSERT_TRUE(studio().save());
  EXPECT_FALSE(Document::has_recovery(scene_file_));
  EXPECT_FALSE(studio().document()->modified());
  const scene::Reconfigurable saved = scene::load_scene(scene_file_);
  EXPECT_NEAR(saved.pose_at(0, saved.find_part("seat"), 0.5).translation.x(), pose.translation.x(), 1e-12);
}

TEST_F(StudioHeadless, ABadFileIsAMessageNotACrash) {
  const std::filesystem::path bad = scene_file_.parent_path() / "bad.json";
  std::ofstream(bad) << R"({"format": "reconfig-scene", "version": 1, "parts": [{"name": 3}]})";
  EXPECT_FALSE(studio().open(bad));
  EXPECT_NE(studio().status().find("bad.json"), std::string::npos);
  EXPECT_NE(studio().status().find("parts"), std::string::npos) << studio().status();
  // What was open stays open and usable.
  ASSERT_NE(studio().document(), nullptr);
  EXPECT_EQ(studio().document()->file(), std::filesystem::absolute(scene_file_));
  frontend_->run_frame();
  EXPECT_FALSE(studio().open(scene_file_.parent_path() / "missing.json"));
  frontend_->run_frame();
}

TEST_F(StudioHeadless, ADesignWithoutStatesIsRefusedWithAMessage) {
  const std::filesystem::path stateless = scene_file_.parent_path() / "stateless.json";
  std::ofstream(stateless) << R"({"format": "reconfig-scene", "version": 1,
    "parts": [{"name": "cube", "box": {"size": [1, 1, 1]}}], "states": []})";
  EXPECT_FALSE(studio().open(stateless));
  EXPECT_NE(studio().status().find("stateless.json: states: the design has no states"), std::string::npos)
      << studio().status();
  ASSERT_NE(studio().document(), nullptr);
  EXPECT_EQ(studio().document()->file(), std::filesystem::absolute(scene_file_));
  frontend_->run_frame();
}

TEST_F(StudioHeadless, CollisionSettingsDetectAgainAndBadOnesAreRefused) {
  const int unfold = studio().document()->scene().find_transition("unfold");
  ASSERT_GE(unfold, 0);
  studio().open_transition(unfold);
  frontend_->run_frame();
  const std::vector<collision::CollisionInterval> before = shown(unfold).frames;
  ASSERT_FALSE(before.empty());  // the unfold choreography collides

  collision::DetectorOptions bad = studio().detector_options();
  bad.tolerance = -1;
  EXPECT_FALSE(studio().set_detector_options(bad));
  EXPECT_NE(studio().status().find("tolerance"), std::string::npos) << studio().status();
  EXPECT_EQ(studio().detector_options().tolerance, collision::DetectorOptions{}.tolerance);

  // Exact boxes (and box-shaped bounds): the same collisions, each frame's box within the
  // rounded one shown before, some strictly smaller.
  collision::DetectorOptions exact = studio().detector_options();
  exact.box_resolution = 0;
  exact.dop = collision::DopFamily::k8;
  ASSERT_TRUE(studio().set_detector_options(exact)) << studio().status();
  EXPECT_EQ(studio().detector_options().box_resolution, 0.0);
  ASSERT_TRUE(frontend_->run_until_collisions_current(milliseconds(60000)));
  const std::vector<collision::CollisionInterval> after = shown(unfold).frames;
  ASSERT_EQ(after.size(), before.size());
  bool smaller = false;
  for (std::size_t i = 0; i < after.size(); ++i) {
    EXPECT_EQ(after[i].parts, before[i].parts);
    EXPECT_EQ(after[i].t0, before[i].t0);
    EXPECT_EQ(after[i].t1, before[i].t1);
    EXPECT_TRUE(before[i].box.contains(after[i].box)) << "frame group " << i;
    smaller = smaller || !after[i].box.isApprox(before[i].box);
  }
  EXPECT_TRUE(smaller);

  // The settings window edits a draft: the settings in use change only with its Apply button.
  studio().show_collision_settings();
  frontend_->run_frame();
  frontend_->run_frame();
  EXPECT_EQ(studio().detector_options().dop, collision::DopFamily::k8);
  EXPECT_EQ(studio().detector_options().box_resolution, 0.0);
}

TEST_F(StudioHeadless, CollisionSettingsAreSavedWithTheDesignAndUndone) {
  collision::DetectorOptions coarse = studio().detector_options();
  coarse.tolerance = 4e-3;
  coarse.frame = 0.05;
  ASSERT_TRUE(studio().set_detector_options(coarse)) << studio().status();
  EXPECT_TRUE(studio().document()->modified());
  EXPECT_EQ(studio().document()->scene().collision.tolerance, 4e-3);
  EXPECT_EQ(studio().document()->undo_label(), "change collision settings");

  // Undo gives back the studio's settings (the design had none); redo the new ones.
  ASSERT_TRUE(studio().undo());
  EXPECT_TRUE(studio().document()->scene().collision.empty());
  EXPECT_EQ(studio().detector_options().tolerance, collision::DetectorOptions{}.tolerance);
  ASSERT_TRUE(studio().redo());
  EXPECT_EQ(studio().detector_options().tolerance, 4e-3);
  EXPECT_EQ(studio().detector_options().frame, 0.05);

  // Saved, and back when the design is opened again, over the studio's own defaults.
  ASSERT_TRUE(studio().save());
  EXPECT_EQ(scene::load_scene(scene_file_).collision.tolerance, 4e-3);
  ASSERT_TRUE(studio().open(scene_file_)) << studio().status();
  EXPECT_EQ(studio().detector_options().tolerance, 4e-3);
  EXPECT_EQ(studio().detector_options().frame, 0.05);
  EXPECT_FALSE(studio().document()->modified());
  ASSERT_TRUE(frontend_->run_until_collisions_current(milliseconds(60000)));
}

// Drag the out handle of the backrest's first translation key in the viewport: the motion
// leaves its state another way (the key's point stays), as one undoable edit.
TEST_F(StudioHeadless, DraggingABezierHandleReshapesThePath) {
  const auto& scene = studio().document()->scene();
  const int unfold = scene.find_transition("unfold");
  click(*studio().graph_edge_point(unfold));
  ASSERT_EQ(studio().active_transition(), unfold);
  click(studio().timeline_point(0.5));
  // Seen from the side: from the front (the first view) the handle points at the camera, and
  // its end sits on its key.
  studio().camera().yaw = -1.0;
  studio().camera().pitch = 0.45;
  studio().frame_all();
  frontend_->run_frame();
  const int backrest = scene.find_part("backrest");
  const auto on_backrest = visible_point(studio(), backrest);
  ASSERT_TRUE(on_backrest);
  click(*on_backrest);
  ASSERT_EQ(studio().selected_part(), backrest);
  const motion::TranslationKey before = track("backrest").translation.front();

  const Eigen::Vector3d pivot = scene.parts[backrest].center;
  const Eigen::Vector3d end = pivot + before.out;
  input().mouse = *studio().viewport_point(end);
  frontend_->run_frame();
  input().buttons[0] = true;
  frontend_->run_frame();
  const Eigen::Vector3d shift(0, 0, 0.1);
  for (int i = 1; i <= 6; ++i) {
    input().mouse = *studio().viewport_point(end + shift * i / 6);
    frontend_->run_frame();
  }
  input().buttons[0] = false;
  frontend_->run_frame();

  const motion::TranslationKey after = track("backrest").translation.front();
  EXPECT_EQ(after.point, before.point);
  EXPECT_EQ(after.in, before.in);
  // The handle's end followed the mouse in the plane facing the camera: under the pixel it was
  // dropped at, and the move seen on screen is the shift's.
  const auto dropped = studio().viewport_point(pivot + after.out), expected = studio().viewport_point(end + shift);
  EXPECT_NEAR(dropped->x, expected->x, 1.0);
  EXPECT_NEAR(dropped->y, expected->y, 1.0);
  EXPECT_GT((after.out - before.out).norm(), 0.05);
  ASSERT_TRUE(studio().selected_key());
  EXPECT_EQ(studio().selected_key()->index, 0);
  EXPECT_TRUE(studio().document()->modified());
  EXPECT_TRUE(studio().document()->scene().pose_at(unfold, backrest, 0.0).translation.isApprox(before.point));

  press(keys::kZ, true);
  EXPECT_EQ(track("backrest").translation.front().out, before.out);

  // The same drag, scripted.
  run_script(*frontend_, "drag-handle 0 out 0 0 0.1\n", "handles.txt");
  EXPECT_EQ(track("backrest").translation.front().point, before.point);
  EXPECT_NEAR((track("backrest").translation.front().out - after.out).norm(), 0, 1e-3);
  EXPECT_THROW(run_script(*frontend_, "drag-handle 7 out 0 0 0.1\n", "handles.txt"), ScriptError);
  EXPECT_THROW(run_script(*frontend_, "drag-handle 0 sideways 0 0 0.1\n", "handles.txt"), ScriptError);
}

TEST_F(StudioHeadless, RefusedEditsLeaveTheDesignUntouched) {
  studio().select_part(studio().document()->scene().find_part("backrest"));
  studio().set_time(0.0);
  press('I');  // no key at an end of the transition
  EXPECT_NE(studio().status().find("inner time"), std::string::npos);
  EXPECT_FALSE(studio().document()->modified());
}

}  // namespace
}  // namespace reconfig::studio
