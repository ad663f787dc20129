#include "frame_times.h"

#include <gtest/gtest.h>

namespace reconfig::studio {
namespace {

TEST(FrameTimes, SummarizesUnsortedSamples) {
  std::vector<double> times;
  for (int i = 100; i >= 1; --i) times.push_back(i);  // 1 … 100 ms, in reverse
  const FrameTimes stats = summarize_frame_times(times);
  EXPECT_EQ(stats.frames, 100);
  EXPECT_DOUBLE_EQ(stats.mean, 50.5);
  EXPECT_DOUBLE_EQ(stats.median, 51);  // index 50 of the sorted samples
  EXPECT_DOUBLE_EQ(stats.p95, 96);     // index 95
  EXPECT_DOUBLE_EQ(stats.max, 100);
  EXPECT_EQ(summarize_frame_times({}).frames, 0);
  EXPECT_DOUBLE_EQ(summarize_frame_times({7}).p95, 7);
}

}  // namespace
}  // namespace reconfig::studio
