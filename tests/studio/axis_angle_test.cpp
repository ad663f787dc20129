// The inspector's rotation: an angle about an axis that stays put while a part turns about one
// axis, where Euler angles jumped (a door turned ~61° read `180, 180, 118.94`).

#include "axis_angle.h"

#include <gtest/gtest.h>

#include <numbers>
#include <random>

namespace reconfig::studio {
namespace {

Eigen::Quaterniond turn(double degrees, const Eigen::Vector3d& axis) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(degrees * std::numbers::pi / 180, axis.normalized()));
}

TEST(AxisAngle, ADoorTurningAboutItsHingeKeepsItsAxisAndItsAngleGrows) {
  for (const Eigen::Vector3d& hinge : {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0.3, -0.2, 0.9).normalized()})
    for (double degrees = 5; degrees < 180; degrees += 5) {
      const AxisAngle shown = axis_angle_of(turn(degrees, hinge));
      EXPECT_NEAR(shown.degrees, degrees, 1e-9);
      EXPECT_TRUE(shown.axis.isApprox(hinge, 1e-12)) << shown.axis.transpose();
    }
}

TEST(AxisAngle, TheIssuesDoorReadsSixtyOneDegreesAboutMinusZ) {
  // Euler x, y, z about fixed axes of (180, 180, 118.94) is this rotation.
  const AxisAngle shown = axis_angle_of(turn(-61.06, Eigen::Vector3d::UnitZ()));
  EXPECT_NEAR(shown.degrees, 61.06, 1e-9);
  EXPECT_TRUE(shown.axis.isApprox(-Eigen::Vector3d::UnitZ(), 1e-12));
}

TEST(AxisAngle, TheIdentityIsNoTurnAboutZ) {
  const AxisAngle shown = axis_angle_of(Eigen::Quaterniond::Identity());
  EXPECT_EQ(shown.degrees, 0);
  EXPECT_EQ(shown.axis, Eigen::Vector3d::UnitZ());
}

TEST(AxisAngle, EditsReadBackAsTheRotationShown) {
  std::mt19937 random(5);
  std::normal_distribution<double> normal;
  for (int i = 0; i < 100; ++i) {
    const Eigen::Quaterniond q = Eigen::Quaterniond(normal(random), normal(random), normal(random), normal(random)).normalized();
    const auto back = rotation_of(axis_angle_of(q));
    ASSERT_TRUE(back);
    EXPECT_LT(back->angularDistance(q), 1e-12);
  }
  // An axis of any length; a zero axis is no rotation to apply.
  EXPECT_LT(rotation_of({Eigen::Vector3d(0, 0, 5), 90})->angularDistance(turn(90, Eigen::Vector3d::UnitZ())), 1e-15);
  EXPECT_FALSE(rotation_of({Eigen::Vector3d::Zero(), 90}));
}

}  // namespace
}  // namespace reconfig::studio
