#include "reconfig/motion/slerp_rotation_track.h"

#include "random_motion.h"
#include "reconfig/motion/key_error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace reconfig::motion;
using namespace reconfig::motion::testing;

double rotation_distance(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return (a.toRotationMatrix() - b.toRotationMatrix()).norm();
}

TEST(SlerpRotationTrack, EndpointsUnitNormAndClamp) {
  std::mt19937 rng(21);
  const SlerpRotationTrack track = random_rotation_track(rng, 6);
  for (const RotationKey& k : track.keys()) {
    EXPECT_NEAR(k.rotation.norm(), 1.0, 1e-15);
    EXPECT_LT(rotation_distance(track.evaluate(k.time), k.rotation), 1e-14);
  }
  std::uniform_real_distribution<double> u(track.start_time() - 1, track.end_time() + 1);
  for (int i = 0; i < 200; ++i) EXPECT_NEAR(track.evaluate(u(rng)).norm(), 1.0, 1e-14);
  EXPECT_LT(rotation_distance(track.evaluate(-10), track.keys().front().rotation), 1e-15);
  EXPECT_LT(rotation_distance(track.evaluate(1e3), track.keys().back().rotation), 1e-15);
}

TEST(SlerpRotationTrack, MatchesEigenSlerpAndTakesShortestArc) {
  std::mt19937 rng(22);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Quaterniond a = random_rotation(rng);
    Eigen::Quaterniond b = random_rotation(rng);
    const SlerpRotationTrack track({{0.0, a}, {2.0, b}});
    // Eigen's slerp also takes the shortest arc.
    for (double g : {0.1, 0.3, 0.5, 0.9}) {
      EXPECT_LT(rotation_distance(track.evaluate(2 * g), a.slerp(g, b)), 1e-12);
    }
    // Turning angle at the midpoint is half the total, and the total is <= π.
    const double total = a.angularDistance(b);
    EXPECT_LE(total, M_PI + 1e-12);
    EXPECT_NEAR(a.angularDistance(track.evaluate(1.0)), 0.5 * total, 1e-12);
    EXPECT_NEAR(track.segment_rotation_vector(0).norm(), total, 1e-12);
  }
}

TEST(SlerpRotationTrack, OppositeQuaternionsGiveAConstantRotation) {
  std::mt19937 rng(23);
  const Eigen::Quaterniond a = random_rotation(rng);
  const SlerpRotationTrack track({{0.0, a}, {1.0, Eigen::Quaterniond(-a.coeffs())}});
  for (double t = 0; t <= 1.0; t += 0.125) {
    EXPECT_LT(rotation_distance(track.evaluate(t), a), 1e-15);
    EXPECT_EQ(track.angular_velocity(t + 1e-3), Eigen::Vector3d::Zero());
  }
}

TEST(SlerpRotationTrack, NearlyIdenticalKeysAreSmooth) {
  std::mt19937 rng(24);
  const Eigen::Quaterniond a = random_rotation(rng);
  const Eigen::Vector3d axis = random_vector(rng).normalized();
  for (double eps : {1e-6, 1e-10, 1e-14, 0.0}) {
    const Eigen::Quaterniond b = Eigen::Quaterniond(Eigen::AngleAxisd(eps, axis)) * a;
    const SlerpRotationTrack track({{0.0, a}, {1.0, b}});
    for (double g = 0; g <= 1.0; g += 0.25) {
      const Eigen::Quaterniond expected = Eigen::Quaterniond(Eigen::AngleAxisd(g * eps, axis)) * a;
      EXPECT_LT(rotation_distance(track.evaluate(g), expected), 1e-15) << eps;
      EXPECT_TRUE(track.evaluate(g).coeffs().allFinite());
    }
    EXPECT_LT((track.angular_velocity(0.5) - eps * axis).norm(), 1e-15);
  }
}

TEST(SlerpRotationTrack, HalfTurnFollowsTheStoredSigns) {
  // 180° about z: both arcs are minimal; the stored quaternion's vector part decides.
  const Eigen::Quaterniond a = Eigen::Quaterniond::Identity();
  const SlerpRotationTrack plus({{0.0, a}, {1.0, Eigen::Quaterniond(0, 0, 0, 1)}});
  const SlerpRotationTrack minus({{0.0, a}, {1.0, Eigen::Quaterniond(0, 0, 0, -1)}});
  EXPECT_LT((plus.angular_velocity(0.5) - Eigen::Vector3d(0, 0, M_PI)).norm(), 1e-14);
  EXPECT_LT((minus.angular_velocity(0.5) - Eigen::Vector3d(0, 0, -M_PI)).norm(), 1e-14);
  EXPECT_LT((plus.evaluate(0.5) * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).norm(),
            1e-15);
}

TEST(SlerpRotationTrack, AngularVelocityMatchesFiniteDifferences) {
  std::mt19937 rng(25);
  for (int trial = 0; trial < 20; ++trial) {
    const SlerpRotationTrack track = random_rotation_track(rng, 5, 3.0);
    for (int k = 0; k < 10; ++k) {
      const double t = random_time_off_keys(rng, track);
      const double h = 1e-6;
      const Eigen::Matrix3d R = track.evaluate(t).toRotationMatrix();
      const Eigen::Matrix3d dR = (track.evaluate(t + h).toRotationMatrix() -
                                  track.evaluate(t - h).toRotationMatrix()) /
                                 (2 * h);
      const Eigen::Matrix3d W = dR * R.transpose();  // = [ω]×
      const Eigen::Vector3d w(W(2, 1), W(0, 2), W(1, 0));
      EXPECT_LT((track.angular_velocity(t) - w).norm(), 1e-6 * (1 + w.norm()));
    }
  }
}

TEST(SlerpRotationTrack, ValidationNamesTheKey) {
  try {
    SlerpRotationTrack track({{0.0, Eigen::Quaterniond::Identity()},
                              {1.0, Eigen::Quaterniond(0, 0, 0, 0)}});
    FAIL() << "expected KeyError";
  } catch (const KeyError& e) {
    EXPECT_EQ(e.key(), 1u);
    EXPECT_EQ(e.field(), "quaternion");
  }
  EXPECT_THROW(SlerpRotationTrack({{1.0, Eigen::Quaterniond::Identity()},
                                   {0.5, Eigen::Quaterniond::Identity()}}),
               std::invalid_argument);
  EXPECT_THROW(SlerpRotationTrack({}), KeyError);
}

}  // namespace
