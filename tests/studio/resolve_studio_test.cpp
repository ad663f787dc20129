// Hints and automatic resolution in the studio, driven headless.

#include <gtest/gtest.h>

#include <fstream>

#include "keys.h"
#include "script.h"
#include "support/test_data.h"
#include "studio_test_util.h"

namespace reconfig::studio {
namespace {

using std::chrono::milliseconds;

class StudioResolve : public ::testing::Test {
 protected:
  void SetUp() override {
    StudioOptions options;
    options.autosave_interval = milliseconds(0);
    frontend_ = std::make_unique<HeadlessFrontend>(1000, 700, options);
    ASSERT_TRUE(studio().open(bench_table_copy())) << studio().status();
    unfold_ = studio().document()->scene().find_transition("unfold");
    backrest_ = studio().document()->scene().find_part("backrest");
    studio().open_transition(unfold_);
    studio().select_part(backrest_);
    frontend_->run_frame();
    ASSERT_TRUE(frontend_->run_until_collisions_current(milliseconds(60000)));
  }

  Studio& studio() { return frontend_->studio(); }

  void press(int key) {
    frontend_->input().keys_down.insert(key);
    frontend_->run_frame();
    frontend_->input().keys_down.clear();
    frontend_->run_frame();
  }

  std::size_t intervals_shown() {
    for (const auto& t : studio().collisions()->transitions)
      if (t.transition == unfold_) return t.intervals.size();
    return 0;
  }

  std::unique_ptr<HeadlessFrontend> frontend_;
  int unfold_ = -1, backrest_ = -1;
};

TEST_F(StudioResolve, HTellsHowToMoveTheSelectedPartAndTheSliderFollowsIt) {
  ASSERT_EQ(intervals_shown(), 2u);  // the backrest hits both armrests
  press(keys::kH);
  const auto& hint = studio().resolution_hint();
  ASSERT_TRUE(hint.has_value()) << studio().status();
  EXPECT_GT(hint->result.energy, 0);
  ASSERT_GE(hint->steepest, 0);
  EXPECT_NE(studio().status().find("hint: move the"), std::string::npos) << studio().status();
  // Slide the steepest handle along its hint (live steps, then a release), and the energy falls.
  const double before = hint->result.energy;
  for (double amount : {0.05, 0.1, 0.15}) ASSERT_TRUE(studio().slide_along_hint(amount, true)) << studio().status();
  ASSERT_TRUE(studio().slide_along_hint(0.2)) << studio().status();
  ASSERT_TRUE(frontend_->run_until_collisions_current(milliseconds(60000)));
  press(keys::kH);
  const double after = studio().resolution_hint() ? studio().resolution_hint()->result.energy : 0.0;
  EXPECT_LT(after, before);
  // The whole slide is one undoable edit.
  ASSERT_TRUE(studio().undo());
  ASSERT_TRUE(frontend_->run_until_collisions_current(milliseconds(60000)));
  EXPECT_EQ(intervals_shown(), 2u);
  EXPECT_FALSE(studio().undo());  // nothing before the slide
}

TEST_F(StudioResolve, AutomaticResolutionIsOneUndoableEdit) {
  ASSERT_EQ(intervals_shown(), 2u);
  ASSERT_TRUE(studio().start_auto_resolve());
  for (int i = 0; i < 2000 && studio().auto_resolving(); ++i) frontend_->run_frame();
  ASSERT_FALSE(studio().auto_resolving());
  EXPECT_NE(studio().status().find("resolved unfold automatically"), std::string::npos) << studio().status();
  ASSERT_TRUE(frontend_->run_until_collisions_current(milliseconds(60000)));
  EXPECT_EQ(intervals_shown(), 0u);
  ASSERT_TRUE(studio().undo());
  ASSERT_TRUE(frontend_->run_until_collisions_current(milliseconds(60000)));
  EXPECT_EQ(intervals_shown(), 2u);
}

TEST_F(StudioResolve, ScriptsHintSlideAndResolve) {
  run_script(*frontend_,
             "expect-collisions 2\n"
             "key H\n"
             "expect-status hint: move the\n"
             "slide-hint 0.2\n"
             "wait-collisions\n"
             "key ctrl+z\n"
             "resolve-auto 60\n"
             "wait-collisions\n"
             "expect-collisions 0\n"
             "expect-status resolved unfold automatically\n",
             "resolve script");
  EXPECT_THROW(run_script(*frontend_, "slide-hint abc\n", "bad amount"), ScriptError);
}

TEST_F(StudioResolve, AHintIsForTheDesignItWasGivenFor) {
  ASSERT_TRUE(studio().request_hint()) << studio().status();
  // Another edit: the hint no longer describes the design, and the slider does not apply it.
  studio().set_time(0.5);
  ASSERT_TRUE(studio().insert_key()) << studio().status();
  EXPECT_FALSE(studio().slide_along_hint(0.1));
  EXPECT_NE(studio().status().find("press H"), std::string::npos) << studio().status();
  // Opening a design drops the hint (it named parts of the other one).
  ASSERT_TRUE(studio().request_hint()) << studio().status();
  ASSERT_TRUE(studio().open(bench_table_copy())) << studio().status();
  EXPECT_FALSE(studio().resolution_hint().has_value());
  frontend_->run_frame();
}

TEST(StudioResolveBackground, ABigDesignsHintArrivesWithoutBlockingTheFrames) {
  StudioOptions options;
  options.autosave_interval = milliseconds(0);
  options.background_hint_triangles = 0;  // every hint in the background
  HeadlessFrontend frontend(1000, 700, options);
  Studio& studio = frontend.studio();
  ASSERT_TRUE(studio.open(bench_table_copy())) << studio.status();
  studio.open_transition(studio.document()->scene().find_transition("unfold"));
  studio.select_part(studio.document()->scene().find_part("backrest"));
  frontend.run_frame();
  ASSERT_TRUE(frontend.run_until_collisions_current(milliseconds(60000)));
  ASSERT_TRUE(studio.request_hint()) << studio.status();
  EXPECT_TRUE(studio.hint_pending());
  EXPECT_NE(studio.status().find("computing"), std::string::npos) << studio.status();
  run_script(frontend, "wait-hint 60\n", "wait for the hint");
  ASSERT_FALSE(studio.hint_pending());
  ASSERT_TRUE(studio.resolution_hint().has_value());
  EXPECT_GT(studio.resolution_hint()->result.energy, 0);
  EXPECT_NE(studio.status().find("hint: move the"), std::string::npos) << studio.status();
  // A hint that arrives after an edit is dropped.
  ASSERT_TRUE(studio.request_hint());
  studio.set_time(0.5);
  ASSERT_TRUE(studio.insert_key()) << studio.status();
  for (int i = 0; i < 5000 && studio.hint_pending(); ++i) frontend.run_frame();
  EXPECT_NE(studio.status().find("hint dropped"), std::string::npos) << studio.status();
}

TEST_F(StudioResolve, NoHintWithoutACollision) {
  studio().select_part(studio().document()->scene().find_part("seat"));
  EXPECT_FALSE(studio().request_hint());
  EXPECT_NE(studio().status().find("does not collide"), std::string::npos) << studio().status();
}

// A box that slides along x and stops half inside a still block (the end state itself
// collides), and a transition back to the start from there.
constexpr const char* kEndInside = R"({
  "format": "reconfig-scene", "version": 1, "units": "m",
  "parts": [{"name": "block", "box": {"size": [1, 1, 1]}}, {"name": "mover", "box": {"size": [0.5, 0.5, 0.5]}}],
  "states": [
    {"name": "start", "poses": {"mover": {"translation": [-3, 0, 0], "rotation": [1, 0, 0, 0]}}},
    {"name": "end", "poses": {"mover": {"translation": [-0.6, 0, 0], "rotation": [1, 0, 0, 0]}}}
  ],
  "transitions": [
    {"name": "go", "from": "start", "to": "end", "tracks": {"mover": {"translation": [
      {"time": 0.0, "point": [-3, 0, 0], "in": [-3, 0, 0], "out": [-2.2, 0, 0]},
      {"time": 1.0, "point": [-0.6, 0, 0], "in": [-1.4, 0, 0], "out": [-0.6, 0, 0]}]}}},
    {"name": "back", "from": "end", "to": "start", "tracks": {"mover": {"translation": [
      {"time": 0.0, "point": [-0.6, 0, 0], "in": [-0.6, 0, 0], "out": [-1.4, 0, 0]},
      {"time": 1.0, "point": [-3, 0, 0], "in": [-2.2, 0, 0], "out": [-3, 0, 0]}]}}}
  ]
})";

TEST(StudioResolveStates, ACollidingStateMovesOnlyWhenAllowedAndUndoPutsItBack) {
  const std::filesystem::path file = testing::fresh_temp_dir() / "end-inside.json";
  std::ofstream(file) << kEndInside;
  StudioOptions options;
  options.autosave_interval = milliseconds(0);
  HeadlessFrontend frontend(1000, 700, options);
  Studio& studio = frontend.studio();
  ASSERT_TRUE(studio.open(file)) << studio.status();
  studio.open_transition(0);
  const auto end_pose = [&] {
    const scene::Reconfigurable& scene = studio.document()->scene();
    return scene.states[scene.find_state("end")].pose_of("mover").translation;
  };
  const Eigen::Vector3d before = end_pose();
  run_script(frontend,
             "wait-collisions\n"
             "expect-collisions 1\n"
             "resolve-auto 60\n"
             "wait-collisions\n"
             "expect-collisions 1\n",  // the end keys are the state's pose: nothing to move
             "states fixed");
  EXPECT_EQ(end_pose(), before);
  run_script(frontend,
             "resolve-auto 60 move-states\n"
             "wait-collisions\n"
             "expect-collisions 0\n"
             "expect-status resolved go automatically\n",
             "states free");
  EXPECT_NE(end_pose(), before);
  // "back" starts in the moved state.
  const scene::Reconfigurable& scene = studio.document()->scene();
  EXPECT_EQ(scene.pose_at(1, scene.find_part("mover"), 0.0).translation, end_pose());
  ASSERT_TRUE(studio.undo());  // one step: the state and both transitions
  EXPECT_EQ(end_pose(), before);
  EXPECT_EQ(studio.document()->scene().pose_at(1, 1, 0.0).translation, before);
}

}  // namespace
}  // namespace reconfig::studio
