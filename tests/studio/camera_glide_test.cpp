#include "camera_glide.h"

#include <gtest/gtest.h>

#include <cmath>

namespace reconfig::studio {
namespace {

view::Camera camera(double yaw, double pitch, double distance, const Eigen::Vector3d& target) {
  view::Camera c;
  c.yaw = yaw;
  c.pitch = pitch;
  c.distance = distance;
  c.target = target;
  return c;
}

TEST(CameraGlide, StartsAndEndsAtItsViewsAndTurnsTheShortWayRound) {
  const CameraGlide glide{camera(3.0, 0.2, 1, {0, 0, 0}), camera(-3.0, 1.0, 4, {1, 2, 3}), 10.0, 0.5};
  EXPECT_NEAR((glide.at(9).eye() - glide.from.eye()).norm(), 0, 1e-12);
  EXPECT_NEAR((glide.at(10.5).eye() - glide.to.eye()).norm(), 0, 1e-12);
  EXPECT_TRUE(glide.done(10.5));
  EXPECT_FALSE(glide.done(10.49));
  // From yaw 3 to −3 is 0.28 rad across ±π, not 6 rad back: every step stays near π.
  for (double t = 10; t <= 10.5; t += 0.05) EXPECT_GT(std::abs(glide.at(t).yaw), 2.9) << t;
  // Eased: slow at both ends, the middle halfway (in log distance too).
  const view::Camera middle = glide.at(10.25);
  EXPECT_NEAR((middle.target - Eigen::Vector3d(0.5, 1, 1.5)).norm(), 0, 1e-12);
  EXPECT_NEAR(middle.distance, 2, 1e-12);
  EXPECT_LT((glide.at(10.025).target - glide.from.target).norm(), 0.05 * (glide.to.target - glide.from.target).norm());
}

}  // namespace
}  // namespace reconfig::studio
