#include "reconfig/motion/motion_bounds.h"

#include "random_motion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

namespace {

using namespace reconfig::motion;
using namespace reconfig::motion::testing;

/// Points on the sphere of radius r about c (Fibonacci lattice), its center, and random
/// points inside.
std::vector<Eigen::Vector3d> ball_points(std::mt19937& rng, const Eigen::Vector3d& c, double r) {
  std::vector<Eigen::Vector3d> pts{c};
  const int n = 48;
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double phi = i * M_PI * (3.0 - std::sqrt(5.0));
    const double rho = std::sqrt(1 - z * z);
    pts.push_back(c + r * Eigen::Vector3d(rho * std::cos(phi), rho * std::sin(phi), z));
  }
  for (int i = 0; i < 8; ++i) {
    Eigen::Vector3d d = random_vector(rng);
    if (d.norm() > 1) d.normalize();
    pts.push_back(c + r * d);
  }
  return pts;
}

/// Sampled sup over points and times of the deviation from the chord and of the
/// displacement, for the motion p ↦ place(t, p).
template <class Place>
MotionBound sample(const Place& place, const std::vector<Eigen::Vector3d>& pts, double t0,
                   double t1, int steps = 400) {
  MotionBound m;
  for (const Eigen::Vector3d& p : pts) {
    const Eigen::Vector3d v0 = place(t0, p), v1 = place(t1, p);
    for (int k = 0; k <= steps; ++k) {
      const double w = double(k) / steps;
      const double t = t0 + w * (t1 - t0);
      const Eigen::Vector3d v = place(t, p);
      m.deviation = std::max(m.deviation, (v - ((1 - w) * v0 + w * v1)).norm());
      m.displacement = std::max(m.displacement, (v - v0).norm());
    }
  }
  return m;
}

ScrewTrack random_screw_track(std::mt19937& rng, int n, const Eigen::Vector3d& c) {
  std::vector<ScrewKey> keys;
  Eigen::Quaterniond q = random_rotation(rng);
  std::uniform_real_distribution<double> angle(0.0, 2.5);
  for (double s : random_times(rng, n)) {
    keys.push_back({s, Pose{q, random_vector(rng, 2.0)}});
    q = Eigen::Quaterniond(Eigen::AngleAxisd(angle(rng), random_vector(rng).normalized())) * q;
  }
  return ScrewTrack(keys, c);
}

struct Looseness {
  std::vector<double> ratios;
  void add(double bound, double sampled) {
    if (sampled > 1e-6) ratios.push_back(bound / sampled);
  }
  double max() const { return *std::max_element(ratios.begin(), ratios.end()); }
  double median() {
    std::sort(ratios.begin(), ratios.end());
    return ratios[ratios.size() / 2];
  }
};

TEST(MotionBounds, KeyframedBoundHoldsAndIsReasonablyTight) {
  std::mt19937 rng(61);
  Looseness dev, disp;
  for (int trial = 0; trial < 40; ++trial) {
    const BezierTranslationTrack x = random_translation_track(rng, 4);
    const SlerpRotationTrack R = random_rotation_track(rng, 4, 2.5);
    const Eigen::Vector3d c = random_vector(rng);
    const double r = std::uniform_real_distribution<double>(0.0, 1.5)(rng);
    const auto pts = ball_points(rng, c, r);
    const auto place = [&](double t, const Eigen::Vector3d& p) {
      return Eigen::Vector3d(R.evaluate(t) * (p - c) + c + x.evaluate(t));
    };
    // Short intervals (mostly inside one segment), long ones (across keys and beyond the
    // ends of the tracks).
    std::uniform_real_distribution<double> start(-0.3, std::max(x.end_time(), R.end_time()));
    for (double width : {0.02, 0.15, 0.6, 2.5}) {
      const double t0 = start(rng), t1 = t0 + width;
      const MotionBound b = keyframed_motion_bound(x, R, r, t0, t1);
      const MotionBound s = sample(place, pts, t0, t1);
      EXPECT_GE(b.deviation, s.deviation - 1e-12) << trial << " [" << t0 << ", " << t1 << "]";
      EXPECT_GE(b.displacement, s.displacement - 1e-12) << trial;
      dev.add(b.deviation, s.deviation);
      disp.add(b.displacement, s.displacement);
      if (width <= 0.02) {
        EXPECT_LE(b.deviation, 3.0 * s.deviation + 1e-6) << trial;
      }
    }
  }
  std::printf("keyframed: deviation bound/sampled median %.2f max %.2f; displacement median %.2f max %.2f\n",
              dev.median(), dev.max(), disp.median(), disp.max());
  EXPECT_LT(dev.median(), 2.0);
  EXPECT_LT(dev.max(), 6.0);
  EXPECT_LT(disp.max(), 3.0);
}

TEST(MotionBounds, ScrewBoundHoldsAndIsReasonablyTight) {
  std::mt19937 rng(62);
  Looseness dev, disp;
  for (int trial = 0; trial < 40; ++trial) {
    const Eigen::Vector3d c = random_vector(rng);
    const ScrewTrack track = random_screw_track(rng, 4, c);
    const double r = std::uniform_real_distribution<double>(0.0, 1.5)(rng);
    const auto pts = ball_points(rng, c, r);
    const auto place = [&](double t, const Eigen::Vector3d& p) {
      return Eigen::Vector3d(track.at(t) * p);
    };
    std::uniform_real_distribution<double> start(-0.3, track.end_time());
    for (double width : {0.02, 0.15, 0.6, 2.5}) {
      const double t0 = start(rng), t1 = t0 + width;
      const MotionBound b = screw_motion_bound(track, r, t0, t1);
      const MotionBound s = sample(place, pts, t0, t1);
      EXPECT_GE(b.deviation, s.deviation - 1e-12) << trial << " [" << t0 << ", " << t1 << "]";
      EXPECT_GE(b.displacement, s.displacement - 1e-12) << trial;
      dev.add(b.deviation, s.deviation);
      disp.add(b.displacement, s.displacement);
      if (width <= 0.02) {
        EXPECT_LE(b.deviation, 3.0 * s.deviation + 1e-6) << trial;
      }
    }
  }
  std::printf("screw: deviation bound/sampled median %.2f max %.2f; displacement median %.2f max %.2f\n",
              dev.median(), dev.max(), disp.median(), disp.max());
  EXPECT_LT(dev.median(), 2.0);
  EXPECT_LT(dev.max(), 6.0);
  EXPECT_LT(disp.max(), 3.0);
}

TEST(MotionBounds, NearlyStraightScrewsGiveTinyFiniteBounds) {
  // Angles down to 0: the axis runs off to infinity but the bound must not.
  const Eigen::Vector3d c(0.5, 0.0, 0.0);
  for (double b : {1e-3, 1e-9, 1e-13, 0.0}) {
    const Pose p0{};
    const Pose p1{Eigen::Quaterniond(Eigen::AngleAxisd(b, Eigen::Vector3d::UnitZ())),
                  Eigen::Vector3d(1.0, 2.0, 0.5)};
    const ScrewTrack track({{0.0, p0}, {1.0, p1}}, c);
    const MotionBound bound = screw_motion_bound(track, 0.0, 0.0, 1.0);
    EXPECT_TRUE(std::isfinite(bound.deviation));
    EXPECT_LE(bound.deviation, 1e-15 + 5.0 * b) << b;  // ~ ρ b² / 8 = |o| b / 16
    EXPECT_NEAR(bound.displacement, std::sqrt(1 + 4 + 0.25), 1e-3 * b + 1e-12);
  }
}

TEST(MotionBounds, ShrinkQuadraticallyAndVanishOnConstantPieces) {
  std::mt19937 rng(63);
  const BezierTranslationTrack x = random_translation_track(rng, 3);
  const SlerpRotationTrack R = random_rotation_track(rng, 3);
  const double t = 0.5 * (x.keys()[0].time + x.keys()[1].time);
  const double big = keyframed_motion_bound(x, R, 1.0, t, t + 0.02).deviation;
  const double small = keyframed_motion_bound(x, R, 1.0, t, t + 0.01).deviation;
  EXPECT_GT(big, 0.0);
  EXPECT_NEAR(small / big, 0.25, 0.1);
  // Entirely before the tracks start: nothing moves.
  const MotionBound before = keyframed_motion_bound(x, R, 1.0, -3.0, -2.0);
  EXPECT_EQ(before.deviation, 0.0);
  EXPECT_EQ(before.displacement, 0.0);
  EXPECT_EQ(keyframed_motion_bound(x, R, 1.0, 0.3, 0.3).deviation, 0.0);
}

TEST(MotionBounds, AdaptiveSamplesMeetTheTolerance) {
  std::mt19937 rng(64);
  const Eigen::Vector3d c = random_vector(rng);
  const ScrewTrack track = random_screw_track(rng, 5, c);
  const double r = 0.8, tol = 1e-3;
  const auto bound = [&](double a, double b) { return screw_motion_bound(track, r, a, b).deviation; };
  const AdaptiveSamples adaptive = adaptive_time_samples(bound, track.start_time(), track.end_time(), tol);
  const std::vector<double>& samples = adaptive.times;
  double largest = 0;
  for (std::size_t i = 0; i + 1 < samples.size(); ++i) largest = std::max(largest, bound(samples[i], samples[i + 1]));
  EXPECT_EQ(adaptive.deviation, largest);
  EXPECT_LE(adaptive.deviation, tol);
  ASSERT_GE(samples.size(), 3u);
  EXPECT_EQ(samples.front(), track.start_time());
  EXPECT_EQ(samples.back(), track.end_time());
  EXPECT_TRUE(std::is_sorted(samples.begin(), samples.end()));
  const auto pts = ball_points(rng, c, r);
  const auto place = [&](double t, const Eigen::Vector3d& p) { return Eigen::Vector3d(track.at(t) * p); };
  for (std::size_t i = 0; i + 1 < samples.size(); ++i)
    EXPECT_LE(sample(place, pts, samples[i], samples[i + 1], 20).deviation, tol);
  // Not wildly oversampled: a deviation ~ L ψ²/8 bound needs ~ sqrt(total/tol) steps.
  EXPECT_LT(samples.size(), 2000u);
}

}  // namespace
