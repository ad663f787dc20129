#include "reconfig/linkage/motion_range.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "linkage_test_util.h"
#include "reconfig/linkage/newton_kinematics.h"

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
  // Eq. (6) drops to zero at the dead point and is clear of it in between.
  const Linkage linkage = test::example("peaucellier_lipkin.json");
  const SymbolicKinematics kinematics(linkage, order_joints(linkage));
  Eigen::Matrix2Xd X;
  ASSERT_TRUE(kinematics.solve(range.upper, X));
  const auto at_end = kinematics.singularity_distances(X);
  EXPECT_LT(*std::min_element(at_end.begin(), at_end.end()), 1e-6);
  ASSERT_TRUE(kinematics.solve(0.0, X));
  const auto inside = kinematics.singularity_distances(X);
  ASSERT_EQ(inside.size(), 3u);
  EXPECT_GT(*std::min_element(inside.begin(), inside.end()), 0.1);
  const std::string text = range.describe();
  EXPECT_EQ(text,
            "rocks between -82.8° and 82.8° (at both ends: triangle (\"O\", \"A\") -> \"B\" flattens (a dead "
            "point) and cannot close beyond)");
}

TEST(MotionRange, AComplexLoopLocksWhereTheNewtonBaselineStopsToo) {
  const Linkage linkage = test::example("triad_complex_loop.json");
  const SymbolicKinematics kinematics(linkage, order_joints(linkage));
  const MotionRange range = motion_range(kinematics);
  ASSERT_FALSE(range.full_rotation);
  EXPECT_EQ(range.upper_failure.kind, ReconstructionFailure::Kind::kNewtonFailed);
  EXPECT_EQ(range.upper_failure.message, "complex loop {\"P1\", \"P2\", \"P3\"} locks (a dead point)");
  // The rigid-body baseline, continued from the initial configuration, converges just inside
  // each end and cannot satisfy the constraints just outside.
  for (const double end : {range.lower, range.upper}) {
    const double inward = end < kinematics.initial_angle() ? 1 : -1;
    NewtonKinematics newton(linkage);
    Eigen::Matrix2Xd X;
    const int steps = 100;
    for (int s = 1; s <= steps; ++s) {
      const double angle = kinematics.initial_angle() + (end + inward * 1e-3 - kinematics.initial_angle()) * s / steps;
      ASSERT_TRUE(newton.solve(angle, X)) << angle;
    }
    EXPECT_FALSE(newton.solve(end - inward * 1e-2, X)) << end;
  }
  Eigen::Matrix2Xd X;
  ReconstructionFailure failure;
  kinematics.reset_continuation();
  EXPECT_FALSE(kinematics.solve(range.upper + 0.05, X, &failure));
  EXPECT_EQ(failure.kind, ReconstructionFailure::Kind::kNewtonFailed);
  EXPECT_NE(failure.message.find("did not converge"), std::string::npos) << failure.message;
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
