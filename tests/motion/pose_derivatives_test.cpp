#include "reconfig/motion/pose_derivatives.h"

#include "random_motion.h"

#include <gtest/gtest.h>

#include <map>

namespace {

using namespace reconfig::motion;
using namespace reconfig::motion::testing;

Eigen::Vector3d moved_point(const BezierTranslationTrack& x, const SlerpRotationTrack& R,
                            const Eigen::Vector3d& c, const Eigen::Vector3d& p, double t) {
  return R.evaluate(t) * (p - c) + c + x.evaluate(t);
}

/// Central-difference ∂v/∂(translation key j, parameter column k).
Eigen::Vector3d fd_translation(const BezierTranslationTrack& x, const SlerpRotationTrack& R,
                               const Eigen::Vector3d& c, const Eigen::Vector3d& p, double t,
                               std::size_t j, int k, double h) {
  auto perturbed = [&](double e) {
    std::vector<TranslationKey> keys = x.keys();
    TranslationKey& key = keys[j];
    if (k < 3) key.in[k] += e;
    else if (k < 6) key.point[k - 3] += e;
    else if (k < 9) key.out[k - 6] += e;
    else key.time += e;
    return moved_point(BezierTranslationTrack(keys), R, c, p, t);
  };
  return (perturbed(h) - perturbed(-h)) / (2 * h);
}

Eigen::Vector3d fd_rotation(const BezierTranslationTrack& x, const SlerpRotationTrack& R,
                            const Eigen::Vector3d& c, const Eigen::Vector3d& p, double t,
                            std::size_t j, int k, double h) {
  auto perturbed = [&](double e) {
    std::vector<RotationKey> keys = R.keys();
    RotationKey& key = keys[j];
    if (k < 3) key.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(e, Eigen::Vector3d::Unit(k))) *
                              key.rotation;
    else key.time += e;
    return moved_point(x, SlerpRotationTrack(keys), c, p, t);
  };
  return (perturbed(h) - perturbed(-h)) / (2 * h);
}

void check_all_entries(const BezierTranslationTrack& x, const SlerpRotationTrack& R,
                       const Eigen::Vector3d& c, const Eigen::Vector3d& p, double t) {
  const KeyframeJacobian J = keyframe_jacobian(x, R, c, p, t);
  const double h = 1e-6, tol = 2e-6;
  std::map<std::size_t, Eigen::Matrix<double, 3, 10>> tj;
  for (const auto& b : J.translation) tj[b.key] = b.jacobian;
  for (std::size_t j = 0; j < x.keys().size(); ++j) {
    for (int k = 0; k < 10; ++k) {
      const Eigen::Vector3d fd = fd_translation(x, R, c, p, t, j, k, h);
      const Eigen::Vector3d an = tj.count(j) ? Eigen::Vector3d(tj[j].col(k)) : Eigen::Vector3d::Zero();
      EXPECT_LT((an - fd).norm(), tol * (1 + fd.norm())) << "t=" << t << " key " << j << " col " << k;
    }
  }
  std::map<std::size_t, Eigen::Matrix<double, 3, 4>> rj;
  for (const auto& b : J.rotation) rj[b.key] = b.jacobian;
  for (std::size_t j = 0; j < R.keys().size(); ++j) {
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector3d fd = fd_rotation(x, R, c, p, t, j, k, h);
      const Eigen::Vector3d an = rj.count(j) ? Eigen::Vector3d(rj[j].col(k)) : Eigen::Vector3d::Zero();
      EXPECT_LT((an - fd).norm(), tol * (1 + fd.norm())) << "t=" << t << " rot key " << j << " col " << k;
    }
  }
  // ∂v/∂p = R(t).
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(k);
    const Eigen::Vector3d fd = (moved_point(x, R, c, p + e, t) - moved_point(x, R, c, p - e, t)) / (2 * h);
    EXPECT_LT((J.rest_point.col(k) - fd).norm(), tol);
  }
}

TEST(PoseDerivatives, EveryEntryMatchesFiniteDifferences) {
  std::mt19937 rng(51);
  for (int trial = 0; trial < 12; ++trial) {
    const BezierTranslationTrack x = random_translation_track(rng, 4);
    const SlerpRotationTrack R = random_rotation_track(rng, 4, 2.8);
    const Eigen::Vector3d c = random_vector(rng, 1.0);
    const Eigen::Vector3d p = c + random_vector(rng, 1.5);
    // Times inside both tracks (they have different key times) and away from all keys.
    for (int k = 0; k < 3; ++k) {
      const double t = random_time_off_keys(rng, x);
      bool near_rotation_key = false;
      for (const auto& key : R.keys()) near_rotation_key |= std::abs(key.time - t) < 1e-3;
      if (near_rotation_key) continue;
      check_all_entries(x, R, c, p, t);
    }
  }
}

TEST(PoseDerivatives, ClampedRegionsAndSingleKeys) {
  std::mt19937 rng(52);
  const BezierTranslationTrack x = random_translation_track(rng, 3);
  const SlerpRotationTrack R = random_rotation_track(rng, 3);
  const Eigen::Vector3d c = random_vector(rng), p = random_vector(rng, 2.0);
  check_all_entries(x, R, c, p, -0.5);
  check_all_entries(x, R, c, p, std::max(x.end_time(), R.end_time()) + 0.5);
  const BezierTranslationTrack x1({{0.3, {1, 2, 3}, {0, 0, 0}, {0, 0, 0}}});
  const SlerpRotationTrack R1({{0.2, random_rotation(rng)}});
  check_all_entries(x1, R1, c, p, 0.25);
}

TEST(PoseDerivatives, NearlyIdenticalRotationKeys) {
  std::mt19937 rng(53);
  const Eigen::Quaterniond a = random_rotation(rng);
  const Eigen::Vector3d axis = random_vector(rng).normalized();
  const BezierTranslationTrack x = random_translation_track(rng, 2);
  for (double eps : {1e-3, 1e-7, 0.0}) {
    const SlerpRotationTrack R(
        {{x.start_time(), a},
         {x.end_time(), Eigen::Quaterniond(Eigen::AngleAxisd(eps, axis)) * a}});
    const KeyframeJacobian J =
        keyframe_jacobian(x, R, Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 0.5, 0), 0.4 * (x.start_time() + x.end_time()) + 0.1);
    for (const auto& b : J.rotation) EXPECT_TRUE(b.jacobian.allFinite());
    check_all_entries(x, R, Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 0.5, 0),
                      0.5 * (x.start_time() + x.end_time()) + 0.01);
  }
}

TEST(PoseDerivatives, TranslationBlocksMatchThePaperAtAKnownPoint) {
  // One segment from s=0 to s=2, evaluated at t=0.5 (f = 1/4).
  std::vector<TranslationKey> keys(2);
  keys[0] = {0.0, {0, 0, 0}, {0, 0, 0}, {1, 0, 0}};
  keys[1] = {2.0, {1, 1, 0}, {1, 0.5, 0}, {0, 0, 0}};
  const auto J = translation_jacobian(BezierTranslationTrack(keys), 0.5);
  ASSERT_EQ(J.size(), 2u);
  const double f = 0.25, g = 0.75;
  EXPECT_NEAR(J[0].jacobian(0, 3), g * g * g, 1e-15);          // ∂x/∂t_j, eq. 19
  EXPECT_NEAR(J[0].jacobian(1, 7), 3 * g * g * f, 1e-15);      // ∂x/∂w_j, eq. 20
  EXPECT_NEAR(J[1].jacobian(2, 2), 3 * g * f * f, 1e-15);      // ∂x/∂u_{j+1}
  EXPECT_NEAR(J[1].jacobian(0, 5), 0.0, 0.0);                  // no cross-talk between axes
  EXPECT_TRUE(J[0].jacobian.leftCols(3).isZero(0.0));  // u_j unused here
  EXPECT_TRUE(J[1].jacobian.middleCols(6, 3).isZero(0.0));  // w_{j+1} unused
}

}  // namespace
