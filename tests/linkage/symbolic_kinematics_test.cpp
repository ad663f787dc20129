#include "reconfig/linkage/symbolic_kinematics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "linkage_test_util.h"
#include "reconfig/common/input_error.h"
#include "reconfig/linkage/motion_range.h"
#include "reconfig/linkage/newton_kinematics.h"

namespace reconfig::linkage {
namespace {

constexpr double kPi = std::numbers::pi;
double radians(double degrees) { return degrees * kPi / 180; }

SymbolicKinematics kinematics_of(const Linkage& linkage) { return SymbolicKinematics(linkage, order_joints(linkage)); }

// Largest violation of a link length, relative to the initial configuration.
double length_error(const Linkage& linkage, const Eigen::Matrix2Xd& X) {
  const Eigen::Matrix2Xd X0 = linkage.initial_positions();
  double worst = 0;
  for (const auto& link : linkage.links)
    for (int a : link)
      for (int b : link)
        worst = std::max(worst, std::abs((X.col(a) - X.col(b)).norm() - (X0.col(a) - X0.col(b)).norm()));
  return worst;
}

// Orientation (sign of the cross product) of every triple of joints of every link.
bool links_keep_orientation(const Linkage& linkage, const Eigen::Matrix2Xd& X) {
  const Eigen::Matrix2Xd X0 = linkage.initial_positions();
  auto orientation = [](const Eigen::Matrix2Xd& Y, int a, int b, int c) {
    const Eigen::Vector2d u = Y.col(b) - Y.col(a), v = Y.col(c) - Y.col(a);
    return u.x() * v.y() - u.y() * v.x();
  };
  for (const auto& link : linkage.links)
    for (std::size_t c = 2; c < link.size(); ++c) {
      const double before = orientation(X0, link[0], link[1], link[c]);
      if (std::abs(before) < 1e-9) continue;
      if (before * orientation(X, link[0], link[1], link[c]) <= 0) return false;
    }
  return true;
}

TEST(SymbolicKinematics, ReproducesTheInitialConfiguration) {
  for (const char* name : test::kExamples) {
    const Linkage linkage = test::example(name);
    const SymbolicKinematics kinematics = kinematics_of(linkage);
    Eigen::Matrix2Xd X;
    ASSERT_TRUE(kinematics.solve(linkage.initial_motor_angle(), X)) << name;
    EXPECT_LT((X - linkage.initial_positions()).cwiseAbs().maxCoeff(), 1e-11) << name;
  }
}

TEST(SymbolicKinematics, KeepsLengthsAndOrientationOverTheMotion) {
  for (const char* name : test::kExamples) {
    const Linkage linkage = test::example(name);
    const SymbolicKinematics kinematics = kinematics_of(linkage);
    const MotionRange range = motion_range(kinematics);
    Eigen::Matrix2Xd X;
    for (int s = 0; s <= 90; ++s) {
      const double angle = range.lower + (range.upper - range.lower) * s / 90.0;
      ASSERT_TRUE(kinematics.solve(angle, X)) << name << " at " << angle;
      EXPECT_LT(length_error(linkage, X), 1e-10) << name;
      EXPECT_TRUE(links_keep_orientation(linkage, X)) << name;
      EXPECT_NEAR(std::remainder(std::atan2(X(1, linkage.motor.joint) - X(1, linkage.motor.center),
                                            X(0, linkage.motor.joint) - X(0, linkage.motor.center)) - angle,
                                 2 * kPi),
                  0, 1e-12);
    }
  }
}

TEST(SymbolicKinematics, PeaucellierLipkinTracerStaysOnItsLine) {
  const Linkage linkage = test::example("peaucellier_lipkin.json");
  const SymbolicKinematics kinematics = kinematics_of(linkage);
  const int P = linkage.find_joint("P");
  const MotionRange range = motion_range(kinematics);
  ASSERT_FALSE(range.full_rotation);
  Eigen::Matrix2Xd X;
  double y_min = 1e9, y_max = -1e9;
  // At the dead points themselves the tracer's position is ill-conditioned (it moves like
  // the square root of the angle's distance to them), so stay 1e-4 rad inside.
  for (int s = 0; s <= 1000; ++s) {
    const double angle = range.lower + 1e-4 + (range.upper - range.lower - 2e-4) * s / 1000.0;
    ASSERT_TRUE(kinematics.solve(angle, X));
    EXPECT_NEAR(X(0, P), 2.625, 1e-12) << angle;  // x = (2.5² − 1²) / (2 · 1)
    y_min = std::min(y_min, X(1, P)), y_max = std::max(y_max, X(1, P));
  }
  EXPECT_GT(y_max - y_min, 2.0);  // and it really moves along the line
}

TEST(SymbolicKinematics, JansenFootPathIsClosedPeriodicWithAFlatBottom) {
  const Linkage linkage = test::example("jansen.json");
  const SymbolicKinematics kinematics = kinematics_of(linkage);
  ASSERT_TRUE(motion_range(kinematics).full_rotation);
  const int foot = linkage.find_joint("P");
  Eigen::Matrix2Xd X, Y;
  std::vector<Eigen::Vector2d> path;
  for (int s = 0; s < 360; ++s) {
    ASSERT_TRUE(kinematics.solve(radians(s), X));
    ASSERT_TRUE(kinematics.solve(radians(s) + 2 * kPi, Y));  // periodic
    EXPECT_LT((X - Y).cwiseAbs().maxCoeff(), 1e-10);
    path.push_back(X.col(foot));
  }
  // Closed: consecutive samples are close, including the last to the first.
  double step_max = 0, y_min = 1e9, y_max = -1e9, x_min = 1e9, x_max = -1e9;
  for (std::size_t s = 0; s < path.size(); ++s) {
    step_max = std::max(step_max, (path[(s + 1) % path.size()] - path[s]).norm());
    y_min = std::min(y_min, path[s].y()), y_max = std::max(y_max, path[s].y());
    x_min = std::min(x_min, path[s].x()), x_max = std::max(x_max, path[s].x());
  }
  EXPECT_LT(step_max, 2.5);
  // Known shape (Jansen's numbers, crank 15): a stride of 67.9 units, a lift of 22.5, and a
  // flat bottom: the foot stays within 1 unit of its lowest point over more than a third of
  // the cycle, along more than half of the stride.
  EXPECT_NEAR(x_max - x_min, 67.9, 0.5);
  EXPECT_NEAR(y_max - y_min, 22.5, 0.5);
  int flat = 0;
  double flat_x_min = 1e9, flat_x_max = -1e9;
  for (const auto& p : path)
    if (p.y() < y_min + 1.0) ++flat, flat_x_min = std::min(flat_x_min, p.x()), flat_x_max = std::max(flat_x_max, p.x());
  EXPECT_GT(flat, 120);
  EXPECT_GT(flat_x_max - flat_x_min, 0.5 * (x_max - x_min));
}

TEST(SymbolicKinematics, AgreesWithTheNewtonBaseline) {
  for (const char* name : test::kExamples) {
    const Linkage linkage = test::example(name);
    const SymbolicKinematics kinematics = kinematics_of(linkage);
    const MotionRange range = motion_range(kinematics);
    NewtonKinematics newton(linkage);
    Eigen::Matrix2Xd X, Y;
    double worst = 0;
    const int samples = range.full_rotation ? 72 : 40;
    const double margin = range.full_rotation ? 0 : 0.02 * (range.upper - range.lower);
    // Walk from the initial angle up to the upper end, then back down to the lower end.
    std::vector<double> angles;
    for (int s = 0; s <= samples; ++s) angles.push_back(kinematics.initial_angle() + (range.upper - margin - kinematics.initial_angle()) * s / samples);
    for (int s = 2 * samples; s >= 0; --s) angles.push_back(range.lower + margin + (range.upper - range.lower - 2 * margin) * s / (2 * samples));
    for (double angle : angles) {
      ASSERT_TRUE(kinematics.solve(angle, X)) << name;
      ASSERT_TRUE(newton.solve(angle, Y)) << name << " at " << angle;
      worst = std::max(worst, (X - Y).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(worst, 1e-9) << name;
  }
}

TEST(SymbolicKinematics, RandomCrankRockersAgreeWithNewtonAndTurnFully) {
  std::mt19937 rng(12345);
  for (int trial = 0; trial < 30; ++trial) {
    const Linkage linkage = test::random_crank_rocker(rng, 2 * kPi * trial / 30.0);
    const SymbolicKinematics kinematics = kinematics_of(linkage);
    EXPECT_TRUE(motion_range(kinematics).full_rotation) << trial;
    NewtonKinematics newton(linkage);
    Eigen::Matrix2Xd X, Y;
    for (int s = 0; s <= 72; ++s) {
      const double angle = linkage.initial_motor_angle() + 2 * kPi * s / 72.0;
      ASSERT_TRUE(kinematics.solve(angle, X));
      ASSERT_TRUE(newton.solve(angle, Y));
      EXPECT_LT((X - Y).cwiseAbs().maxCoeff(), 1e-9) << trial << " " << s;
    }
  }
}

TEST(SymbolicKinematics, ReportsATriangleThatCannotClose) {
  const Linkage linkage = test::example("peaucellier_lipkin.json");
  const SymbolicKinematics kinematics = kinematics_of(linkage);
  Eigen::Matrix2Xd X;
  ReconstructionFailure failure;
  EXPECT_FALSE(kinematics.solve(radians(150), X, &failure));
  EXPECT_EQ(failure.kind, ReconstructionFailure::Kind::kCannotClose);
  EXPECT_NE(failure.message.find("cannot close"), std::string::npos) << failure.message;
  EXPECT_TRUE(linkage.joints[failure.joint].name == "B" || linkage.joints[failure.joint].name == "D");
}

TEST(SymbolicKinematics, SolvesAComplexLoopWithNewtonAndNamesItsJoints) {
  const Linkage linkage = test::complex_loop();
  const JointOrder order = order_joints(linkage);
  ASSERT_FALSE(order.symbolic());
  std::vector<std::string> stuck;
  for (int k : order.stuck_joints) stuck.push_back(linkage.joints[k].name);
  EXPECT_EQ(stuck, (std::vector<std::string>{"P1", "P2", "P3"}));
  const SymbolicKinematics kinematics(linkage, order);
  NewtonKinematics newton(linkage);
  Eigen::Matrix2Xd X, Y;
  for (int s = 0; s <= 40; ++s) {
    const double angle = radians(-20 + s);
    ASSERT_TRUE(kinematics.solve(angle, X)) << s;
    ASSERT_TRUE(newton.solve(angle, Y)) << s;
    EXPECT_LT((X - Y).cwiseAbs().maxCoeff(), 1e-9) << s;
    EXPECT_LT(length_error(linkage, X), 1e-10);
  }
}

// Central finite differences of the positions with respect to the initial positions.
Eigen::MatrixXd finite_difference_derivatives(const Linkage& linkage, const JointOrder& order, double angle) {
  const Eigen::Matrix2Xd X0 = linkage.initial_positions();
  const Eigen::Index n = X0.cols();
  Eigen::MatrixXd result(2 * n, 2 * n);
  const double h = 1e-6;
  for (Eigen::Index p = 0; p < n; ++p)
    for (int c = 0; c < 2; ++c) {
      Eigen::Matrix2Xd plus = X0, minus = X0;
      plus(c, p) += h, minus(c, p) -= h;
      SymbolicKinematics kinematics(linkage, order);
      Eigen::Matrix2Xd Xp, Xm;
      EXPECT_TRUE(kinematics.set_initial_positions(plus));
      EXPECT_TRUE(kinematics.solve(angle, Xp));
      EXPECT_TRUE(kinematics.set_initial_positions(minus));
      EXPECT_TRUE(kinematics.solve(angle, Xm));
      const Eigen::Matrix2Xd diff = (Xp - Xm) / (2 * h);
      result.col(2 * p + c) = Eigen::Map<const Eigen::VectorXd>(diff.data(), 2 * n);
    }
  return result;
}

void expect_derivatives_match(const Linkage& linkage, double angle, const std::string& what) {
  const JointOrder order = order_joints(linkage);
  const SymbolicKinematics kinematics(linkage, order);
  Eigen::Matrix2Xd X;
  StateDerivatives D;
  ASSERT_TRUE(kinematics.solve(angle, X, D)) << what;
  const Eigen::MatrixXd analytic = D.dense();
  const Eigen::MatrixXd numeric = finite_difference_derivatives(linkage, order, angle);
  const double scale = std::max(1.0, numeric.cwiseAbs().maxCoeff());
  EXPECT_LT((analytic - numeric).cwiseAbs().maxCoeff(), 1e-6 * scale) << what;
}

TEST(StateDerivatives, MatchFiniteDifferencesOnTheExamples) {
  for (const char* name : {"jansen.json", "klann.json", "chebyshev_lambda.json", "peaucellier_lipkin.json",
                           "four_bar_crank_rocker.json", "strandbeest_3.json"}) {
    const Linkage linkage = test::example(name);
    const MotionRange range = motion_range(kinematics_of(linkage));
    for (double t : {0.2, 0.5, 0.9})
      expect_derivatives_match(linkage, range.lower + t * (range.upper - range.lower), name);
  }
}

TEST(StateDerivatives, MatchFiniteDifferencesOnRandomLinkagesAndAComplexLoop) {
  std::mt19937 rng(777);
  for (int trial = 0; trial < 10; ++trial) {
    const Linkage linkage = test::random_crank_rocker(rng, 0.3 * trial);
    expect_derivatives_match(linkage, 0.3 * trial + 1.7, "random " + std::to_string(trial));
  }
  expect_derivatives_match(test::complex_loop(), radians(10), "complex loop");
}

TEST(StateTape, ReverseModeMatchesForwardDerivatives) {
  std::mt19937 rng(5);
  std::normal_distribution<double> normal;
  for (const char* name : test::kExamples) {
    const Linkage linkage = test::example(name);
    const SymbolicKinematics kinematics = kinematics_of(linkage);
    const MotionRange range = motion_range(kinematics);
    const double angle = 0.3 * range.lower + 0.7 * range.upper;
    Eigen::Matrix2Xd X, Y;
    StateDerivatives D;
    StateTape tape;
    kinematics.reset_continuation();
    ASSERT_TRUE(kinematics.solve(angle, X, D)) << name;
    kinematics.reset_continuation();
    ASSERT_TRUE(kinematics.solve(angle, Y, tape)) << name;
    EXPECT_EQ(X, Y);
    Eigen::Matrix2Xd G(2, X.cols());
    for (Eigen::Index i = 0; i < G.size(); ++i) G.data()[i] = normal(rng);
    Eigen::Matrix2Xd forward = Eigen::Matrix2Xd::Zero(2, X.cols()), reverse = forward;
    D.pull_back(G, forward);
    tape.pull_back(G, reverse);
    EXPECT_LT((forward - reverse).cwiseAbs().maxCoeff(), 1e-9 * std::max(1.0, forward.cwiseAbs().maxCoeff())) << name;
  }
}

TEST(StateDerivatives, PullBackIsTheTransposedProduct) {
  const Linkage linkage = test::example("klann.json");
  const SymbolicKinematics kinematics = kinematics_of(linkage);
  Eigen::Matrix2Xd X;
  StateDerivatives D;
  ASSERT_TRUE(kinematics.solve(1.0, X, D));
  std::mt19937 rng(5);
  std::normal_distribution<double> normal;
  Eigen::Matrix2Xd G(2, X.cols());
  for (Eigen::Index i = 0; i < G.size(); ++i) G.data()[i] = normal(rng);
  Eigen::Matrix2Xd out = Eigen::Matrix2Xd::Zero(2, X.cols());
  D.pull_back(G, out);
  const Eigen::VectorXd expected = D.dense().transpose() * Eigen::Map<const Eigen::VectorXd>(G.data(), G.size());
  EXPECT_LT((Eigen::Map<const Eigen::VectorXd>(out.data(), out.size()) - expected).cwiseAbs().maxCoeff(), 1e-12);
}

}  // namespace
}  // namespace reconfig::linkage
