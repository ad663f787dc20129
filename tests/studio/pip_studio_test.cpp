// The picture-in-picture and the jump to a best view (V), driven headless: an edit that
// shortens one collision and creates another elsewhere opens the PIP on the new one at its
// severity time; a click swaps it with the main view; P over a band opens it by hand.

#include <gtest/gtest.h>

#include <fstream>

#include "frontend.h"
#include "keys.h"
#include "reconfig/render/image.h"
#include "script.h"
#include "support/test_data.h"

namespace reconfig::studio {
namespace {

using std::chrono::milliseconds;

// A slider runs along x from −2 to 2 through a block at the origin; a post stands at
// (2, 1.5) beside where it stops.
constexpr const char* kScene = R"({
  "format": "reconfig-scene", "version": 1, "units": "m",
  "parts": [
    {"name": "slider", "box": {"size": [0.5, 0.5, 0.5]}},
    {"name": "block", "box": {"size": [1.2, 1.2, 0.3]}},
    {"name": "post", "box": {"size": [0.4, 0.4, 1.2]}}
  ],
  "states": [
    {"name": "start", "poses": {"slider": {"translation": [-2, 0, 0], "rotation": [1, 0, 0, 0]},
                                "post": {"translation": [2, 1.5, 0], "rotation": [1, 0, 0, 0]}}},
    {"name": "end", "poses": {"slider": {"translation": [2, 0, 0], "rotation": [1, 0, 0, 0]},
                              "post": {"translation": [2, 1.5, 0], "rotation": [1, 0, 0, 0]}}}
  ],
  "transitions": [
    {"name": "slide", "from": "start", "to": "end", "tracks": {"slider": {
      "translation": [
        {"time": 0.0, "point": [-2, 0, 0], "in": [-2, 0, 0], "out": [-0.667, 0, 0]},
        {"time": 1.0, "point": [2, 0, 0], "in": [0.667, 0, 0], "out": [2, 0, 0]}
      ],
      "rotation": [{"time": 0.0, "quaternion": [1, 0, 0, 0]}, {"time": 1.0, "quaternion": [1, 0, 0, 0]}]}}}
  ]
})";

class StudioPip : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::filesystem::path file = testing::fresh_temp_dir() / "slide.json";
    std::ofstream(file) << kScene;
    StudioOptions options;
    options.autosave_interval = milliseconds(0);
    frontend_ = std::make_unique<HeadlessFrontend>(1200, 760, options);
    ASSERT_TRUE(studio().open(file)) << studio().status();
    studio().open_transition(0);
    studio().select_part(0);
    studio().set_time(0.5);
    settle();
  }

  Studio& studio() { return frontend_->studio(); }

  void settle() {
    frontend_->run_frame();
    ASSERT_TRUE(frontend_->run_until_collisions_current(milliseconds(60000)));
    for (int i = 0; i < 3; ++i) frontend_->run_frame();
  }

  std::vector<collision::CollisionInterval> intervals() {
    for (const auto& t : studio().collisions()->transitions)
      if (t.transition == 0) return t.intervals;
    return {};
  }

  void click(const ImVec2& at) {
    frontend_->input().mouse = at;
    frontend_->run_frame();
    frontend_->input().buttons[0] = true;
    frontend_->run_frame();
    frontend_->input().buttons[0] = false;
    frontend_->run_frame();
  }

  std::unique_ptr<HeadlessFrontend> frontend_;
};

TEST_F(StudioPip, AnEditsNewCollisionOpensThePipAtItsSeverityTimeAndAClickSwaps) {
  ASSERT_EQ(intervals().size(), 1u);  // slider × block
  EXPECT_FALSE(studio().pip().target());
  // Bend the slider's end over to the post: it now grazes the block less and hits the post.
  studio().set_time(1.0);
  ASSERT_TRUE(studio().apply_pose({Eigen::Quaterniond::Identity(), Eigen::Vector3d(2, 1.5, 0)})) << studio().status();
  studio().set_time(0.5);
  settle();
  const auto after = intervals();
  ASSERT_EQ(after.size(), 2u);
  const auto& target = studio().pip().target();
  ASSERT_TRUE(target);
  EXPECT_EQ(target->interval.parts, (std::vector<int>{0, 2}));  // the new one, not the one worked on
  EXPECT_GE(target->time, target->interval.t0 - 0.02);
  EXPECT_LE(target->time, target->interval.t1 + 0.02);
  EXPECT_GT(studio().pip().image_max().x, studio().pip().image_min().x);  // on screen
  render::write_png(testing::binary_dir() / "test-tmp" / "studio-pip.png", frontend_->screenshot());

  const double pip_time = target->time;
  const ImVec2 center{(studio().pip().image_min().x + studio().pip().image_max().x) / 2,
                      (studio().pip().image_min().y + studio().pip().image_max().y) / 2};
  click(center);
  EXPECT_NEAR(studio().time(), pip_time, 1e-12);
  EXPECT_EQ(studio().selected_part(), 0);
  ASSERT_TRUE(studio().pip().target());
  EXPECT_EQ(studio().pip().target()->interval.parts, (std::vector<int>{0, 1}));  // the main view's, swapped in
  EXPECT_NEAR(studio().pip().target()->time, 0.5, 1e-12);

  studio().pip().close();
  frontend_->run_frame();
  EXPECT_FALSE(studio().pip().target());
}

// Nearly the same session as a script: at t = 0.9 the gizmo lifts the slider 1.5 along y (a new
// key), into the post; the time stays there, on the new collision, yet the one worked on is
// still slider × block.
TEST_F(StudioPip, AScriptOpensThePipByAnEditAndSwapsItByAClick) {
  run_script(*frontend_,
             "expect-collisions 1\n"
             "expect-pip none\n"
             "scrub 0.9\n"
             "drag-gizmo move-y 1.5\n"
             "wait-collisions\n"
             "frames 3\n"
             "expect-collisions 2\n"
             "expect-pip slider post\n"
             "click-pip\n"
             "expect-selected slider\n"
             "expect-pip slider block\n",
             "pip script");
  EXPECT_THROW(run_script(*frontend_, "expect-pip slider post\n", "wrong pip"), ScriptError);
}

TEST_F(StudioPip, PressingPOverABandOpensItAndVGlidesToTheBestView) {
  const auto before = intervals();
  ASSERT_EQ(before.size(), 1u);
  const ImVec2 band = {studio().timeline_point(0.5 * (before[0].t0 + before[0].t1)).x, studio().layout().bands_row_y};
  frontend_->input().mouse = band;
  frontend_->run_frame();
  frontend_->input().keys_down.insert(keys::kP);
  frontend_->run_frame();
  frontend_->input().keys_down.clear();
  frontend_->run_frame();
  EXPECT_TRUE(studio().pip().searching());  // on its own thread: the frame did not wait
  ASSERT_TRUE(frontend_->run_while_pip_searches(std::chrono::steady_clock::now() + std::chrono::seconds(60)));
  ASSERT_TRUE(studio().pip().target());
  EXPECT_EQ(studio().pip().target()->interval.parts, before[0].parts);

  const Eigen::Vector3d eye_before = studio().camera().eye();
  frontend_->input().mouse = {-1, -1};
  frontend_->input().keys_down.insert(keys::kV);
  frontend_->run_frame();
  frontend_->input().keys_down.clear();
  const Eigen::Vector3d eye_early = studio().camera().eye();
  for (int i = 0; i < 40; ++i) frontend_->run_frame();  // 0.67 s of virtual time: the glide is over
  const view::Camera& camera = studio().camera();
  EXPECT_NEAR((camera.target - before[0].box.center()).norm(), 0, 1e-9);
  EXPECT_GT((camera.eye() - eye_before).norm(), 1e-3);
  EXPECT_GT((camera.eye() - eye_early).norm(), 1e-3);  // it moved on after the first frame: a glide
  // Slider along x, block still: one part holds still, so the view is sampled — from above the floor.
  EXPECT_GE(camera.eye().z(), before[0].box.min().z());
}

}  // namespace
}  // namespace reconfig::studio
