#include "reconfig/linkage/curve_edit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace reconfig::linkage {
namespace {

std::vector<Eigen::Vector2d> circle(int n) {
  std::vector<Eigen::Vector2d> points;
  for (int s = 0; s < n; ++s) {
    const double t = 2 * std::numbers::pi * s / n;
    points.emplace_back(3 + std::cos(t), -1 + std::sin(t));
  }
  return points;
}

TEST(CurveEdit, TransformAboutTheCentroid) {
  const auto curve = circle(36);
  const auto moved = transform_curve(curve, 2.0, 0.3, Eigen::Vector2d(1, 2));
  for (std::size_t s = 0; s < curve.size(); ++s) {
    EXPECT_NEAR((moved[s] - Eigen::Vector2d(4, 1)).norm(), 2.0, 1e-12);  // radius doubled, center moved
    for (std::size_t t = 0; t < curve.size(); t += 7)
      EXPECT_NEAR((moved[s] - moved[t]).norm(), 2 * (curve[s] - curve[t]).norm(), 1e-12);
  }
}

TEST(CurveEdit, SoftDragFallsOffAlongTheCurveAndWrapsWhenClosed) {
  const auto curve = circle(360);
  const Eigen::Vector2d d(0.5, 0);
  const auto closed = soft_drag_curve(curve, 2, d, 0.3, true);
  EXPECT_NEAR((closed[2] - curve[2] - d).norm(), 0, 1e-15);
  // Falls off monotonically with distance along the curve, on both sides.
  for (int s = 3; s < 60; ++s) EXPECT_LT((closed[s] - curve[s]).norm(), (closed[s - 1] - curve[s - 1]).norm());
  EXPECT_LT((closed[180] - curve[180]).norm(), 1e-12);  // the far side does not move
  // The neighbour behind the start (index 358) is 4 steps away round the loop.
  EXPECT_NEAR((closed[358] - curve[358]).norm(), (closed[6] - curve[6]).norm(), 1e-12);
  const auto open = soft_drag_curve(curve, 2, d, 0.3, false);
  EXPECT_LT((open[358] - curve[358]).norm(), 1e-12);  // open: the other end is far
}

}  // namespace
}  // namespace reconfig::linkage
