#include "reconfig/motion/pose.h"

#include <gtest/gtest.h>

#include <random>

namespace {

using reconfig::motion::Pose;

Eigen::Quaterniond random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  return q.normalized();
}

Eigen::Vector3d random_vector(std::mt19937& rng, double scale = 1.0) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

TEST(Pose, ApplyMatchesEquation9) {
  Pose pose;
  pose.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  pose.translation = {1, 2, 3};
  const Eigen::Vector3d c(1, 0, 0);
  const Eigen::Vector3d p(2, 0, 0);
  // p − c = (1,0,0) → rotated (0,1,0) → + c + x = (1,1,0) + (1,2,3) = (2,3,3)
  EXPECT_TRUE(pose.apply(c, p).isApprox(Eigen::Vector3d(2, 3, 3), 1e-14));
  // The center moves by x only.
  EXPECT_TRUE(pose.apply(c, c).isApprox(c + pose.translation, 1e-14));
}

TEST(Pose, IsometryAgreesWithApplyAndRoundTrips) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 100; ++trial) {
    Pose pose;
    pose.rotation = random_rotation(rng);
    pose.translation = random_vector(rng, 5.0);
    const Eigen::Vector3d c = random_vector(rng, 3.0);
    const Eigen::Isometry3d M = pose.to_isometry(c);
    for (int k = 0; k < 5; ++k) {
      const Eigen::Vector3d p = random_vector(rng, 4.0);
      EXPECT_LT((M * p - pose.apply(c, p)).norm(), 1e-12);
    }
    const Eigen::Vector3d c2 = random_vector(rng, 3.0);
    const Pose back = Pose::from_isometry(M, c2);
    EXPECT_LT((back.to_isometry(c2).matrix() - M.matrix()).norm(), 1e-12);
    for (int k = 0; k < 5; ++k) {
      const Eigen::Vector3d p = random_vector(rng, 4.0);
      EXPECT_LT((back.apply(c2, p) - pose.apply(c, p)).norm(), 1e-12);
    }
  }
}

}  // namespace
