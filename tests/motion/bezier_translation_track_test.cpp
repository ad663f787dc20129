#include "reconfig/motion/bezier_translation_track.h"

#include "random_motion.h"
#include "reconfig/motion/key_error.h"

#include <gtest/gtest.h>

namespace {

using namespace reconfig::motion;
using namespace reconfig::motion::testing;

TEST(BezierTranslationTrack, InterpolatesPointsAtKeyTimesAndClamps) {
  std::mt19937 rng(11);
  const BezierTranslationTrack track = random_translation_track(rng, 6);
  for (const TranslationKey& k : track.keys())
    EXPECT_LT((track.evaluate(k.time) - k.point).norm(), 1e-14);
  EXPECT_EQ(track.evaluate(track.start_time() - 5.0), track.keys().front().point);
  EXPECT_EQ(track.evaluate(track.end_time() + 5.0), track.keys().back().point);
  EXPECT_EQ(track.derivative(track.start_time() - 1.0), Eigen::Vector3d::Zero());
  EXPECT_EQ(track.derivative(track.end_time() + 1.0), Eigen::Vector3d::Zero());
}

TEST(BezierTranslationTrack, MatchesEquation11) {
  std::vector<TranslationKey> keys(2);
  keys[0] = {2.0, {0, 0, 0}, {-1, -1, -1}, {1, 0, 0}};
  keys[1] = {4.0, {3, 3, 0}, {3, 0, 0}, {9, 9, 9}};
  const BezierTranslationTrack track(keys);
  for (double f : {0.0, 0.1, 0.25, 0.5, 0.77, 0.99}) {
    const double g = 1 - f;
    const Eigen::Vector3d expected = g * g * g * keys[0].point + 3 * g * g * f * keys[0].out +
                                     3 * g * f * f * keys[1].in + f * f * f * keys[1].point;
    EXPECT_LT((track.evaluate(2.0 + 2.0 * f) - expected).norm(), 1e-14) << f;
  }
  // The handle of the first key and the out handle of the last do not matter.
  EXPECT_LT((track.evaluate(3.0) - Eigen::Vector3d(1.875, 0.375, 0)).norm(), 1e-14);
}

TEST(BezierTranslationTrack, SingleKeyIsConstant) {
  const BezierTranslationTrack track({{1.0, {1, 2, 3}, {0, 0, 0}, {5, 5, 5}}});
  for (double t : {-1.0, 1.0, 2.0}) {
    EXPECT_EQ(track.evaluate(t), Eigen::Vector3d(1, 2, 3));
    EXPECT_EQ(track.derivative(t), Eigen::Vector3d::Zero());
  }
}

TEST(BezierTranslationTrack, DerivativeMatchesFiniteDifferences) {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 20; ++trial) {
    const BezierTranslationTrack track = random_translation_track(rng, 5);
    for (int k = 0; k < 10; ++k) {
      const double t = random_time_off_keys(rng, track);
      const double h = 1e-6;
      const Eigen::Vector3d fd = (track.evaluate(t + h) - track.evaluate(t - h)) / (2 * h);
      EXPECT_LT((track.derivative(t) - fd).norm(), 1e-6 * (1 + fd.norm()));
    }
  }
}

TEST(BezierTranslationTrack, CurveIsContinuousAcrossKeys) {
  std::mt19937 rng(13);
  const BezierTranslationTrack track = random_translation_track(rng, 5);
  for (const TranslationKey& k : track.keys()) {
    EXPECT_LT((track.evaluate(k.time - 1e-10) - track.evaluate(k.time + 1e-10)).norm(), 1e-8);
  }
}

TEST(BezierTranslationTrack, ValidationNamesTheKey) {
  std::vector<TranslationKey> keys(3);
  keys[0].time = 0.0;
  keys[1].time = 1.0;
  keys[2].time = 1.0;
  try {
    BezierTranslationTrack track(keys);
    FAIL() << "expected KeyError";
  } catch (const KeyError& e) {
    EXPECT_EQ(e.key(), 2u);
    EXPECT_EQ(e.field(), "time");
    EXPECT_STREQ(e.what(), "key 2 (time): keyframe times must strictly increase");
  }
  keys[2].time = 2.0;
  keys[1].out.x() = std::nan("");
  try {
    BezierTranslationTrack::validate(keys);
    FAIL() << "expected KeyError";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(dynamic_cast<const KeyError&>(e).key(), 1u);
    EXPECT_EQ(dynamic_cast<const KeyError&>(e).field(), "out");
  }
  EXPECT_THROW(BezierTranslationTrack({}), KeyError);
  keys[1].out.x() = 0.0;
  EXPECT_NO_THROW(BezierTranslationTrack::validate(keys));
}

}  // namespace
