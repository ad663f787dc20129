#include "reconfig/collision/frame_grid.h"

#include <gtest/gtest.h>

#include <random>

namespace reconfig::collision {
namespace {

/// Every instant lies in exactly one frame, found by `frame_of`, for grids whose width does or
/// does not divide 1, at random times and exactly on the frame boundaries.
TEST(FrameGrid, EveryInstantLiesInExactlyOneFrame) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> uniform(0, 1);
  for (double width : {0.01, 0.03, 1.0 / 3, 0.3, 1.0}) {
    const FrameGrid grid(width);
    std::vector<double> times = {0.0, 1.0};
    for (int k = 0; k <= grid.count(); ++k) times.push_back(grid.lo(std::min(k, grid.count() - 1)));
    for (int k = 0; k < grid.count(); ++k) times.push_back(grid.hi(k));
    for (int i = 0; i < 2000; ++i) times.push_back(uniform(random));
    for (double t : times) {
      int holders = 0, holder = -1;
      for (int k = 0; k < grid.count(); ++k)
        if ((k == 0 ? t >= grid.lo(k) : t > grid.lo(k)) && t <= grid.hi(k)) ++holders, holder = k;
      EXPECT_EQ(holders, 1) << "width " << width << " t " << t;
      EXPECT_EQ(grid.frame_of(t), holder) << "width " << width << " t " << t;
    }
    EXPECT_EQ(grid.lo(0), 0.0);
    EXPECT_EQ(grid.hi(grid.count() - 1), 1.0);
  }
}

/// `frames_overlapping` names exactly the frames a range shares a positive time with.
TEST(FrameGrid, OverlappingFramesAreThoseSharingPositiveTime) {
  std::mt19937 random(4);
  std::uniform_real_distribution<double> uniform(0, 1);
  for (double width : {0.01, 0.07, 0.5}) {
    const FrameGrid grid(width);
    for (int i = 0; i < 2000; ++i) {
      double t0 = uniform(random), t1 = uniform(random);
      if (i % 5 == 0) t0 = grid.lo(static_cast<int>(t0 * grid.count()));  // on a boundary
      if (i % 7 == 0) t1 = grid.hi(static_cast<int>(t1 * grid.count()) % grid.count());
      if (t0 > t1) std::swap(t0, t1);
      if (t0 == t1) continue;
      const auto [first, last] = grid.frames_overlapping(t0, t1);
      for (int k = 0; k < grid.count(); ++k) {
        const bool shares = std::min(t1, grid.hi(k)) > std::max(t0, grid.lo(k));
        EXPECT_EQ(shares, k >= first && k <= last) << "width " << width << " [" << t0 << ", " << t1 << "] frame " << k;
      }
    }
  }
}

TEST(FrameGrid, RejectsWidthsOutsideTheUnitInterval) {
  EXPECT_THROW(FrameGrid(0), std::invalid_argument);
  EXPECT_THROW(FrameGrid(-0.1), std::invalid_argument);
  EXPECT_THROW(FrameGrid(1.5), std::invalid_argument);
}

}  // namespace
}  // namespace reconfig::collision
