// Quick key taps are not lost: presses and releases are queued and handed to ImGui one change
// per key per frame, so a tap shorter than a frame still counts (5 taps of Right gave 3 steps;
// tapped Space and F did nothing).

#include "key_queue.h"

#include <gtest/gtest.h>

#include "keys.h"
#include "studio_test_util.h"

namespace reconfig::studio {
namespace {

void tap(KeyQueue& queue, int key, int times = 1) {
  for (int i = 0; i < times; ++i) {
    queue.push({key, true});
    queue.push({key, false});
  }
}

TEST(KeyQueue, EachTapIsDownForOneFrameAndUpTheNext) {
  KeyQueue queue;
  tap(queue, keys::kRight, 3);  // all between two frames
  for (int frame = 0; frame < 6; ++frame) {
    const std::vector<KeyEvent> events = queue.take_frame();
    ASSERT_EQ(events.size(), 1u) << frame;
    EXPECT_EQ(events[0].down, frame % 2 == 0) << frame;
  }
  EXPECT_TRUE(queue.empty());
  EXPECT_TRUE(queue.take_frame().empty());
}

TEST(KeyQueue, AModifierStaysDownAroundTheTapsItWasHeldFor) {
  constexpr int kCtrl = 341;  // GLFW_KEY_LEFT_CONTROL
  KeyQueue queue;
  queue.push({kCtrl, true});
  tap(queue, keys::kZ, 2);
  queue.push({kCtrl, false});
  std::vector<std::vector<KeyEvent>> frames;
  while (!queue.empty()) frames.push_back(queue.take_frame());
  ASSERT_EQ(frames.size(), 4u);  // ctrl+z down | z up | z down | z up, ctrl up
  EXPECT_EQ(frames[0].size(), 2u);
  EXPECT_EQ(frames[3].back().key, kCtrl);
  EXPECT_FALSE(frames[3].back().down);
}

TEST(KeyQueue, FiveQuickTapsOfRightStepFiveFramesInTheStudio) {
  HeadlessFrontend frontend(800, 600);
  Studio& studio = frontend.studio();
  ASSERT_TRUE(studio.open(bench_table_copy())) << studio.status();
  frontend.run_frame();
  studio.set_time(0.5);
  tap(frontend.input().key_events, keys::kRight, 5);
  while (!frontend.input().key_events.empty()) frontend.run_frame();
  frontend.run_frame();
  EXPECT_NEAR(studio.time(), 0.5 + 5 * studio.detector_options().frame, 1e-12);

  tap(frontend.input().key_events, keys::kSpace);  // a tap shorter than a frame
  frontend.run_frame();
  EXPECT_TRUE(studio.playing());
}

}  // namespace
}  // namespace reconfig::studio
