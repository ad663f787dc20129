#include "reconfig/motion/screw_track.h"

#include "random_motion.h"
#include "reconfig/motion/key_error.h"

#include <gtest/gtest.h>

namespace {

using namespace reconfig::motion;
using namespace reconfig::motion::testing;

double distance(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.matrix() - b.matrix()).norm();
}

ScrewTrack random_screw_track(std::mt19937& rng, int n, const Eigen::Vector3d& center) {
  std::vector<ScrewKey> keys;
  for (double s : random_times(rng, n, 0.5)) {
    ScrewKey k;
    k.time = s;
    k.pose.rotation = random_rotation(rng);
    k.pose.translation = random_vector(rng, 2.0);
    keys.push_back(k);
  }
  return ScrewTrack(keys, center);
}

TEST(ScrewTrack, InterpolatesAllKeysAndHoldsOutside) {
  std::mt19937 rng(41);
  const Eigen::Vector3d c(0.3, -0.2, 1.0);
  const ScrewTrack track = random_screw_track(rng, 6, c);
  for (const ScrewKey& k : track.keys()) {
    const Pose p = track.evaluate(k.time);
    EXPECT_EQ(p.translation, k.pose.translation);
    EXPECT_EQ(p.rotation.coeffs(), k.pose.rotation.coeffs());
    EXPECT_LT(distance(track.at(k.time), k.pose.to_isometry(c)), 1e-15);
    // Continuous through the key.
    EXPECT_LT(distance(track.at(k.time - 1e-9), track.at(k.time + 1e-9)), 1e-7);
  }
  EXPECT_LT(distance(track.at(-3.0), track.keys().front().pose.to_isometry(c)), 1e-15);
  EXPECT_LT(distance(track.at(99.0), track.keys().back().pose.to_isometry(c)), 1e-15);
}

TEST(ScrewTrack, EvaluateAgreesWithSegmentsAndCenter) {
  std::mt19937 rng(42);
  const Eigen::Vector3d c(1.0, 2.0, -1.0);
  const ScrewTrack track = random_screw_track(rng, 4, c);
  for (int i = 0; i < 50; ++i) {
    const double t = random_time_off_keys(rng, track);
    const Pose pose = track.evaluate(t);
    const Eigen::Isometry3d M = track.at(t);
    const Eigen::Vector3d p = random_vector(rng, 3.0);
    EXPECT_LT((pose.apply(c, p) - M * p).norm(), 1e-12);
  }
}

TEST(ScrewTrack, KeyPoseInsertionLeavesTheTrackUnchanged) {
  std::mt19937 rng(43);
  const Eigen::Vector3d c(0.1, 0.2, 0.3);
  const ScrewTrack track = random_screw_track(rng, 4, c);
  const double tp = random_time_off_keys(rng, track, 0.05);
  std::vector<ScrewKey> keys = track.keys();
  const ScrewKey inserted{tp, track.evaluate(tp)};
  keys.insert(std::upper_bound(keys.begin(), keys.end(), tp,
                               [](double t, const ScrewKey& k) { return t < k.time; }),
              inserted);
  const ScrewTrack refined(keys, c);
  EXPECT_EQ(refined.segment_count(), track.segment_count() + 1);
  for (double t = track.start_time(); t <= track.end_time(); t += 0.01)
    EXPECT_LT(distance(refined.at(t), track.at(t)), 1e-10) << t;
}

TEST(ScrewTrack, ValidationNamesTheKey) {
  std::vector<ScrewKey> keys(2);
  keys[0].time = 0.0;
  keys[1].time = 1.0;
  keys[1].pose.translation.y() = std::numeric_limits<double>::infinity();
  try {
    ScrewTrack track(keys, Eigen::Vector3d::Zero());
    FAIL() << "expected KeyError";
  } catch (const KeyError& e) {
    EXPECT_EQ(e.key(), 1u);
    EXPECT_EQ(e.field(), "translation");
  }
  keys[1].pose.translation.y() = 0.0;
  keys[0].pose.rotation = Eigen::Quaterniond(0, 0, 0, 0);
  EXPECT_THROW(ScrewTrack::validate(keys), KeyError);
  EXPECT_THROW(ScrewTrack({}, Eigen::Vector3d::Zero()), KeyError);
  const ScrewTrack single({{2.0, Pose{}}}, Eigen::Vector3d::Ones());
  EXPECT_LT(distance(single.at(5.0), Eigen::Isometry3d::Identity()), 1e-15);
}

}  // namespace
