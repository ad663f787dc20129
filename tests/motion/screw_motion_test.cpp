#include "reconfig/motion/screw_motion.h"

#include "random_motion.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace reconfig::motion;
using namespace reconfig::motion::testing;

double distance(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.matrix() - b.matrix()).norm();
}

/// The textbook form: turn by t·b about the line (s, p), slide t·d along s, after A.
Eigen::Isometry3d via_axis_point(const ScrewMotion& m, double t) {
  Eigen::Isometry3d D = Eigen::Isometry3d::Identity();
  D.linear() = Eigen::AngleAxisd(t * m.angle(), m.axis()).toRotationMatrix();
  D.translation() = m.point() - D.linear() * m.point() + t * m.distance() * m.axis();
  return D * m.start();
}

TEST(ScrewMotion, InterpolatesBothPosesAndMatchesAxisPointForm) {
  std::mt19937 rng(31);
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Isometry3d A = random_isometry(rng), B = random_isometry(rng);
    const ScrewMotion m(A, B);
    EXPECT_LT(distance(m.at(0.0), A), 1e-15);
    EXPECT_LT(distance(m.at(1.0), B), 1e-12);
    EXPECT_GE(m.angle(), 0.0);
    EXPECT_LE(m.angle(), M_PI);
    EXPECT_NEAR(m.axis().norm(), 1.0, 1e-14);
    // point() is on the axis closest to the origin: orthogonal to s.
    EXPECT_LT(std::abs(m.point().dot(m.axis())), 1e-9 * (1 + m.point().norm()));
    for (double t : {0.2, 0.5, 0.8, 1.3}) EXPECT_LT(distance(m.at(t), via_axis_point(m, t)), 1e-11);
    // The angle is the minimal one: that between A's and B's orientations.
    const Eigen::Quaterniond qa(A.linear()), qb(B.linear());
    EXPECT_NEAR(m.angle(), qa.angularDistance(qb), 1e-10);
  }
}

TEST(ScrewMotion, PureTranslation) {
  std::mt19937 rng(32);
  const Eigen::Isometry3d A = random_isometry(rng);
  Eigen::Isometry3d B = A;
  const Eigen::Vector3d o(0.3, -2.0, 1.0);
  B.pretranslate(o);
  const ScrewMotion m(A, B);
  EXPECT_TRUE(m.is_translation());
  EXPECT_EQ(m.angle(), 0.0);
  EXPECT_NEAR(m.distance(), o.norm(), 1e-14);
  EXPECT_LT((m.axis() - o.normalized()).norm(), 1e-14);
  for (double t = 0; t <= 1.0; t += 0.1) {
    Eigen::Isometry3d expected = A;
    expected.pretranslate(t * o);
    EXPECT_LT(distance(m.at(t), expected), 1e-14);
  }
  const ScrewMotion still(A, A);
  EXPECT_EQ(still.angle(), 0.0);
  EXPECT_EQ(still.distance(), 0.0);
  EXPECT_LT(distance(still.at(0.7), A), 1e-15);
}

TEST(ScrewMotion, TinyAnglesAreContinuousAndAccurate) {
  std::mt19937 rng(33);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Isometry3d A = random_isometry(rng);
    const Eigen::Vector3d axis = random_vector(rng).normalized();
    const Eigen::Vector3d o = random_vector(rng, 2.0);
    for (double b : {1e-4, 1e-8, 1e-12, 1e-15, 0.0}) {
      // D = turn by b about `axis` through the origin, then translate by o.
      Eigen::Isometry3d D = Eigen::Isometry3d::Identity();
      D.linear() = Eigen::AngleAxisd(b, axis).toRotationMatrix();
      D.translation() = o;
      const ScrewMotion m(A, D * A);
      EXPECT_NEAR(m.angle(), b, 1e-15 + 1e-9 * b);
      for (double t = 0; t <= 1.0; t += 0.125) {
        // To first order in b the motion is the rotation t·b plus the translation t·o.
        Eigen::Isometry3d expected = Eigen::Isometry3d::Identity();
        expected.linear() = Eigen::AngleAxisd(t * b, axis).toRotationMatrix();
        expected.translation() = t * o;
        expected = expected * A;
        const Eigen::Isometry3d got = m.at(t);
        ASSERT_TRUE(got.matrix().allFinite());
        EXPECT_LT(distance(got, expected), 1e-14 + 3.0 * b * o.norm()) << b << " " << t;
      }
      EXPECT_LT(distance(m.at(1.0), D * A), 1e-13);
    }
  }
}

TEST(ScrewMotion, HalfTurnIsDeterministic) {
  std::mt19937 rng(34);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Isometry3d A = random_isometry(rng);
    const Eigen::Vector3d axis = random_vector(rng).normalized();
    const Eigen::Vector3d o = random_vector(rng);
    // The same half turn reached through two different floating-point paths and both axis
    // signs.
    Eigen::Isometry3d D1 = Eigen::Isometry3d::Identity(), D2 = Eigen::Isometry3d::Identity();
    D1.linear() = Eigen::AngleAxisd(M_PI, axis).toRotationMatrix();
    D2.linear() = Eigen::Quaterniond(0, -axis.x(), -axis.y(), -axis.z()).toRotationMatrix();
    D1.translation() = D2.translation() = o;
    const ScrewMotion m1(A, D1 * A), m2(A, D2 * A);
    EXPECT_EQ(m1.angle(), M_PI);
    EXPECT_EQ(m2.angle(), M_PI);
    EXPECT_LT((m1.axis() - m2.axis()).norm(), 1e-12);
    Eigen::Index k = 0;
    m1.axis().cwiseAbs().maxCoeff(&k);
    EXPECT_GT(m1.axis()[k], 0.0);
    for (double t : {0.25, 0.5, 0.75}) EXPECT_LT(distance(m1.at(t), m2.at(t)), 1e-11);
    EXPECT_LT(distance(m1.at(1.0), D1 * A), 1e-11);
    // Same input, same output.
    const ScrewMotion again(A, D1 * A);
    EXPECT_EQ(distance(again.at(0.4), m1.at(0.4)), 0.0);
  }
}

TEST(ScrewMotion, EveryPointMovesOnAHelix) {
  std::mt19937 rng(35);
  for (int trial = 0; trial < 50; ++trial) {
    const ScrewMotion m(random_isometry(rng), random_isometry(rng));
    if (m.angle() < 1e-3) continue;
    const Eigen::Vector3d s = m.axis(), p = m.point();
    const Eigen::Vector3d x = random_vector(rng, 2.0);
    const Eigen::Vector3d y0 = m.at(0) * x;
    const Eigen::Vector3d r0 = (y0 - p) - (y0 - p).dot(s) * s;
    for (double t = 0.0; t <= 1.0; t += 0.1) {
      const Eigen::Vector3d y = m.at(t) * x;
      const Eigen::Vector3d r = (y - p) - (y - p).dot(s) * s;
      EXPECT_NEAR(r.norm(), r0.norm(), 1e-10);                         // constant radius
      EXPECT_NEAR((y - y0).dot(s), t * m.distance(), 1e-10);            // linear advance
      const double turned = std::atan2(r0.cross(r).dot(s), r0.dot(r));  // linear turning
      if (r0.norm() > 1e-3 && t * m.angle() < M_PI - 1e-6) {
        EXPECT_NEAR(turned, t * m.angle(), 1e-8);
      }
    }
  }
}

TEST(ScrewMotion, KeyPoseInsertionLeavesTheMotionUnchanged) {
  std::mt19937 rng(36);
  std::uniform_real_distribution<double> u(0.05, 0.95);
  for (int trial = 0; trial < 50; ++trial) {
    const ScrewMotion m(random_isometry(rng), random_isometry(rng));
    const double tp = u(rng);
    const Eigen::Isometry3d M = m.at(tp);
    const ScrewMotion first(m.start(), M), second(M, m.end());
    for (double t = 0.0; t <= 1.0; t += 1.0 / 64) {
      const Eigen::Isometry3d piecewise =
          t <= tp ? first.at(t / tp) : second.at((t - tp) / (1 - tp));
      EXPECT_LT(distance(piecewise, m.at(t)), 1e-10) << trial << " " << t;
    }
  }
}

TEST(ScrewMotion, IndependentOfWorldAndBodyFrames) {
  std::mt19937 rng(37);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Isometry3d A = random_isometry(rng), B = random_isometry(rng);
    const Eigen::Isometry3d G = random_isometry(rng), H = random_isometry(rng);
    const ScrewMotion m(A, B);
    const ScrewMotion conjugated(G * A * G.inverse(), G * B * G.inverse());
    const ScrewMotion framed(G * A * H, G * B * H);
    for (double t = 0.0; t <= 1.0; t += 0.1) {
      EXPECT_LT(distance(conjugated.at(t), G * m.at(t) * G.inverse()), 1e-11);
      EXPECT_LT(distance(framed.at(t), G * m.at(t) * H), 1e-11);
    }
    EXPECT_NEAR(conjugated.angle(), m.angle(), 1e-10);
    EXPECT_NEAR(conjugated.distance(), m.distance(), 1e-10);
  }
}

TEST(ScrewMotion, ContinuousInItsEndPoses) {
  // A slight change of B changes the motion only slightly (away from the half turn).
  std::mt19937 rng(38);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Isometry3d A = random_isometry(rng), B = random_isometry(rng);
    const ScrewMotion m(A, B);
    if (m.angle() > 3.0) continue;
    Eigen::Isometry3d B2 = B;
    B2.prerotate(Eigen::AngleAxisd(1e-7, random_vector(rng).normalized()));
    B2.pretranslate(1e-7 * random_vector(rng));
    const ScrewMotion m2(A, B2);
    for (double t = 0.0; t <= 1.0; t += 0.25) EXPECT_LT(distance(m.at(t), m2.at(t)), 1e-5);
  }
}

}  // namespace
