#include "resolve/detail/line_search.h"

#include <gtest/gtest.h>

#include <cmath>

namespace reconfig::resolve::detail {
namespace {

TEST(LineSearch, FindsTheMinimumOfAValley) {
  const auto valley = [](double s) { return 1 + (s - 0.3) * (s - 0.3); };
  EXPECT_NEAR(line_search(valley, valley(0), 1.0, 0.01), 0.3, 1e-3);
}

TEST(LineSearch, TakesTheShortestZeroStepPlusTheClearance) {
  // The energy falls to 0 at s = 0.2 and stays 0: every scanned step from 0.25 to 1 is zero.
  const auto escape = [](double s) { return std::max(0.0, 0.2 - s); };
  const double step = line_search(escape, escape(0), 1.0, 0.01);
  EXPECT_NEAR(step, 0.21, 0.005);  // not 1.0, the longest zero step
  EXPECT_EQ(escape(step), 0);
}

TEST(LineSearch, CrossesABarrierToAZeroBeyondIt) {
  // A contained part: its energy rises as its surface starts to cross, then falls to 0 outside.
  const auto barrier = [](double s) { return s < 0.4 ? 1 + s : s < 0.6 ? 2 * (0.6 - s) : 0.0; };
  const double step = line_search(barrier, barrier(0), 1.0, 0.01);
  EXPECT_EQ(barrier(step), 0);
  EXPECT_LT(step, 0.7);
}

TEST(LineSearch, NoStepWhenNothingIsLower) {
  const auto rising = [](double s) { return 1 + s; };
  EXPECT_EQ(line_search(rising, rising(0), 1.0, 0.01), 0);
}

}  // namespace
}  // namespace reconfig::resolve::detail
