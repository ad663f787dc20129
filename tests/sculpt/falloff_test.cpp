#include "reconfig/sculpt/falloff.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace reconfig::sculpt {
namespace {

TEST(Falloff, IsOneInsideZeroBeyondAndC2AtBothEnds) {
  const double coating = 0.3;
  EXPECT_EQ(falloff(-1, coating), 1);
  EXPECT_EQ(falloff(0, coating), 1);
  EXPECT_EQ(falloff(coating, coating), 0);
  EXPECT_EQ(falloff(2, coating), 0);
  const double e = 1e-7;
  for (double d : {1e-12, coating - e - 1e-12}) {  // first and second derivatives vanish at the ends
    EXPECT_NEAR(falloff_slope(d, coating), 0, 1e-10);
    EXPECT_NEAR((falloff_slope(d + e, coating) - falloff_slope(d, coating)) / e, 0, 1e-3);
  }
}

TEST(Falloff, SlopeMatchesFiniteDifferencesAndItsMinimumIsTheBoundsConstant) {
  const double coating = 0.7, e = 1e-6;
  double steepest = 0;
  for (int i = 1; i < 1000; ++i) {
    const double d = coating * i / 1000.0;
    EXPECT_NEAR(falloff_slope(d, coating), (falloff(d + e, coating) - falloff(d - e, coating)) / (2 * e), 1e-7);
    steepest = std::min(steepest, falloff_slope(d, coating));
  }
  EXPECT_NEAR(steepest * coating, -kFalloffSteepestSlope, 1e-12);  // at d = λ/2, sampled exactly
}

}  // namespace
}  // namespace reconfig::sculpt
