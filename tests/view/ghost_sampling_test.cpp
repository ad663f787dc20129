#include "reconfig/view/ghost_sampling.h"

#include <gtest/gtest.h>

namespace reconfig::view {
namespace {

TEST(GhostSampling, RegularSpacingAroundCurrentWithFadingWeights) {
  const auto samples = ghost_samples({.current = 0.5, .count = 2, .spacing = 0.1});
  ASSERT_EQ(samples.size(), 4u);
  const double times[] = {0.3, 0.4, 0.6, 0.7};
  const double weights[] = {0.5, 1.0, 1.0, 0.5};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(samples[i].time, times[i], 1e-12);
    EXPECT_NEAR(samples[i].weight, weights[i], 1e-12);
  }
}

TEST(GhostSampling, DropsTimesOutsideTheTransitionAndHonoursSides) {
  auto samples = ghost_samples({.current = 0.05, .count = 3, .spacing = 0.1});
  ASSERT_EQ(samples.size(), 3u);  // 0.15, 0.25, 0.35; none before 0
  EXPECT_NEAR(samples.front().time, 0.15, 1e-12);
  samples = ghost_samples({.current = 0.5, .count = 3, .spacing = 0.1, .past = false});
  ASSERT_EQ(samples.size(), 3u);
  for (const GhostSample& s : samples) EXPECT_GT(s.time, 0.5);
  EXPECT_TRUE(ghost_samples({.current = 0.5, .count = 0}).empty());
  // The end point itself is kept despite rounding (0.7 + 3 · 0.1).
  samples = ghost_samples({.current = 0.7, .count = 3, .spacing = 0.1, .past = false});
  ASSERT_EQ(samples.size(), 3u);
  EXPECT_DOUBLE_EQ(samples.back().time, 1.0);
}

}  // namespace
}  // namespace reconfig::view
