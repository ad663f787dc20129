#include "reconfig/linkage/motion_range.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "linkage_test_util.h"

namespace reconfig::linkage {
namespace {

constexpr double kPi = std::numbers::pi;

MotionRange range_of(const Linkage& linkage) { return motion_range(SymbolicKinematics(linkage, order_joints(linkage))); }

TEST(MotionRange, CranksTurnFully) {
  for (const char* name : {"jansen.json", "strandbeest_3.json", "strandbeest_10.json", "klann.json",
                           "chebyshev_lambda.json", "four_bar_crank_rocker.json"}) {
    const MotionRange range = range_of(test::example(name));
    EXPECT_TRUE(range.full_rotation) << name << ": " << range.describe();
    EXPECT_EQ(range.describe(), "full rotation");
  }
}

TEST(MotionRange, PeaucellierLipkinRocksBetweenItsAnalyticDeadPoints) {
  // |OA| = 2 cos(θ/2) must stay ≥ 2.5 − 1, so |θ| ≤ 2 acos(0.75).
  const MotionRange range = range_of(test::example("peaucellier_lipkin.json"));
  ASSERT_FALSE(range.full_rotation);
  const double limit = 2 * std::acos(0.75);
  EXPECT_NEAR(range.upper, limit, 1e-9);
  EXPECT_NEAR(range.lower, -limit, 1e-9);
  EXPECT_TRUE(range.contains(0.5));
  EXPECT_TRUE(range.contains(0.5 + 2 * kPi));
  EXPECT_FALSE(range.contains(2.0));
  EXPECT_EQ(range.upper_failure.kind, ReconstructionFailure::Kind::kCannotClose);
  const std::string text = range.describe();
  EXPECT_EQ(text,
            "rocks between -82.8° and 82.8° (at both ends: triangle (\"O\", \"A\") -> \"B\" flattens (a dead "
            "point) and cannot close beyond)");
}

TEST(MotionRange, DoubleRockerMatchesTheLawOfCosines) {
  // Non-Grashof four-bar: ground 3, crank 2, coupler 2, rocker 2.5. The crank stops where
  // the coupler and rocker are stretched out: |BD| = 4.5 = √(2² + 3² − 2·2·3 cos θ).
  Linkage linkage;
  const double theta0 = 1.0;
  const Eigen::Vector2d A(0, 0), D(3, 0), B(2 * std::cos(theta0), 2 * std::sin(theta0));
  const Eigen::Vector2d d = D - B;
  const double dist = d.norm(), a = (dist * dist + 4 - 6.25) / (2 * dist), h = std::sqrt(4 - a * a);
  const Eigen::Vector2d C = B + a * d / dist + h * Eigen::Vector2d(-d.y(), d.x()) / dist;
  linkage.joints = {{"A", A, true}, {"D", D, true}, {"B", B, false}, {"C", C, false}};
  linkage.links = {{0, 2}, {2, 3}, {1, 3}};
  linkage.motor = {0, 2};
  const MotionRange range = range_of(linkage);
  ASSERT_FALSE(range.full_rotation);
  const double limit = std::acos((4 + 9 - 4.5 * 4.5) / 12);
  EXPECT_NEAR(range.upper, limit, 1e-9);
  EXPECT_NEAR(range.lower, -limit, 1e-9);
}

}  // namespace
}  // namespace reconfig::linkage
