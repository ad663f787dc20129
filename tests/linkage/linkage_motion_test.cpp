#include "reconfig/linkage/linkage_motion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "linkage/linkage_test_util.h"
#include "reconfig/common/input_error.h"
#include "reconfig/linkage/joint_order.h"
#include "reconfig/linkage/motion_range.h"

namespace reconfig::linkage {
namespace {

constexpr double kPi = std::numbers::pi;
double rad(double degrees) { return degrees * kPi / 180; }

PlanePlacement tilted_plane() {
  PlanePlacement plane;
  plane.pose = Eigen::Translation3d(0.3, -0.2, 1.0) *
               Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 0.5).normalized());
  plane.scale = 0.01;
  return plane;
}

/// Where the plane puts a linkage point lifted by `z` along the normal.
Eigen::Vector3d embed(const PlanePlacement& plane, const Eigen::Vector2d& x, double z = 0) {
  return plane.pose * Eigen::Vector3d(plane.scale * x.x(), plane.scale * x.y(), z);
}

/// Index of the joint called `name` (the test fails if it is missing).
int joint(const Linkage& linkage, const std::string& name) {
  const int j = linkage.find_joint(name);
  EXPECT_GE(j, 0) << name;
  return j;
}

/// The rocker variant of the crank-rocker four-bar: the motor turns the rocker D–C, which can
/// only rock (between −141.4° and −101.4°).
Linkage rocker() {
  Linkage linkage = test::example("four_bar_crank_rocker.json");
  linkage.motor = {linkage.find_joint("D"), linkage.find_joint("C")};
  return linkage;
}

// Oracle: every joint of every link, carried as a point of a body attached to that link,
// lands where the symbolic kinematics puts the joint (lifted by the offset along the normal).
TEST(LinkageMotion, AttachedPointsFollowTheSymbolicKinematics) {
  for (const char* name : {"jansen.json", "four_bar_crank_rocker.json", "triad_complex_loop.json"}) {
    SCOPED_TRACE(name);
    const Linkage linkage = test::example(name);
    const SymbolicKinematics kinematics(linkage, order_joints(linkage));
    const PlanePlacement plane = tilted_plane();
    const Eigen::Matrix2Xd X0 = linkage.initial_positions();
    const MotionRange range = motion_range(kinematics);
    const double span = range.upper - range.lower;
    const double from = range.full_rotation ? kinematics.initial_angle() + 0.3 : range.lower + 0.05 * span;
    const double to = range.full_rotation ? from + 2 * kPi : range.upper - 0.05 * span;
    const LinkageMotion motion(kinematics, plane, from, to);
    const double lift = 0.04;
    for (const auto& link : linkage.links) {
      LinkAttachment attachment{link[0], link[1], Eigen::Isometry3d(Eigen::Translation3d(0, 0, lift))};
      // Rest coordinates of the link's joints in the link frame at the initial configuration.
      const Eigen::Isometry3d rest = (link_frame(X0, link[0], link[1], plane) * attachment.offset).inverse();
      for (double t : {0.0, 0.1, 0.37, 0.5, 0.81, 1.0}) {
        Eigen::Matrix2Xd X;
        ASSERT_TRUE(kinematics.solve(motion.angle_at(t), X));
        const Eigen::Isometry3d M = motion.maps_at(t, {{attachment, Eigen::Vector3d::Zero(), 0.0}}).front();
        EXPECT_NEAR((M.linear() * M.linear().transpose() - Eigen::Matrix3d::Identity()).norm(), 0, 1e-12);
        for (int j : link) {
          const Eigen::Vector3d p = rest * embed(plane, X0.col(j), lift);
          EXPECT_LT((M * p - embed(plane, X.col(j), lift)).norm(), 1e-11) << "joint " << linkage.joints[j].name
                                                                        << " at t = " << t;
        }
      }
    }
  }
}

TEST(LinkageMotion, LinkFrameHasItsOriginAtTheFirstJointAndXTowardTheSecond) {
  const Linkage linkage = test::example("jansen.json");
  const PlanePlacement plane = tilted_plane();
  const Eigen::Matrix2Xd X = linkage.initial_positions();
  const int c = joint(linkage, "C"), u = joint(linkage, "U");
  const Eigen::Isometry3d F = link_frame(X, c, u, plane);
  EXPECT_LT((F.translation() - embed(plane, X.col(c))).norm(), 1e-15);
  const Eigen::Vector3d x_axis = (embed(plane, X.col(u)) - embed(plane, X.col(c))).normalized();
  EXPECT_LT((F.linear().col(0) - x_axis).norm(), 1e-12);
  EXPECT_LT((F.linear().col(2) - plane.pose.linear().col(2)).norm(), 1e-12);
}

TEST(LinkageMotion, ShareALink) {
  const Linkage linkage = test::example("jansen.json");
  EXPECT_TRUE(share_a_link(linkage, joint(linkage, "B"), joint(linkage, "E")));  // triangle B–U–E
  EXPECT_TRUE(share_a_link(linkage, joint(linkage, "E"), joint(linkage, "U")));
  EXPECT_FALSE(share_a_link(linkage, joint(linkage, "O"), joint(linkage, "B")));  // the ground is no link
  EXPECT_FALSE(share_a_link(linkage, joint(linkage, "C"), joint(linkage, "C")));
}

TEST(LinkageMotion, MotorIntervalsInsideAndOutsideTheMotionRange) {
  const Linkage full = test::example("four_bar_crank_rocker.json");
  const MotionRange turning = motion_range(SymbolicKinematics(full, order_joints(full)));
  EXPECT_EQ(motor_interval_error(turning, rad(-720), rad(720)), "");

  const Linkage rocking = rocker();
  const MotionRange range = motion_range(SymbolicKinematics(rocking, order_joints(rocking)));
  ASSERT_FALSE(range.full_rotation);
  EXPECT_EQ(motor_interval_error(range, rad(-130), rad(-110)), "");
  EXPECT_EQ(motor_interval_error(range, rad(-110), rad(-130)), "");  // backwards
  EXPECT_EQ(motor_interval_error(range, rad(230), rad(250)), "");    // one turn later
  const std::string error = motor_interval_error(range, rad(-130), rad(-90));
  EXPECT_NE(error.find("cannot turn from -130.0° to -90.0°"), std::string::npos) << error;
  EXPECT_NE(error.find("rocks between -141.4° and -101.4°"), std::string::npos) << error;
  EXPECT_NE(motor_interval_error(range, rad(0), rad(360)), "");
  EXPECT_NE(motor_interval_error(range, rad(-150), rad(-120)), "");
}

TEST(LinkageMotion, PlacementDistanceIsExactForTranslationsAndTurns) {
  const Eigen::Vector3d c(1, 2, 3);
  const Eigen::Isometry3d A(Eigen::Translation3d(0.1, 0.2, -0.3));
  EXPECT_NEAR(placement_distance(A, Eigen::Isometry3d::Identity(), c, 5.0), std::sqrt(0.14), 1e-15);
  // A turn by φ about an axis through c moves the points at distance r from c by 2 r sin(φ/2).
  const double phi = 0.4, r = 2.0;
  const Eigen::Isometry3d B = Eigen::Translation3d(c) * Eigen::AngleAxisd(phi, Eigen::Vector3d::UnitY()) *
                              Eigen::Translation3d(-c);
  EXPECT_NEAR(placement_distance(B, Eigen::Isometry3d::Identity(), c, r), 2 * r * std::sin(phi / 2), 1e-14);
  const Eigen::Vector3d p = c + r * Eigen::Vector3d::UnitX();
  EXPECT_NEAR((B * p - p).norm(), 2 * r * std::sin(phi / 2), 1e-14);  // attained
}

/// Largest distance, at `samples` evenly spaced times, between the screw interpolation of the
/// compiled keys and the true motion, over every point of each body's ball.
double dense_deviation(const LinkageMotion& motion, const CompileMotionRequest& request, const CompiledMotion& compiled,
                       int samples) {
  std::vector<motion::ScrewTrack> tracks;
  for (std::size_t b = 0; b < request.bodies.size(); ++b) tracks.emplace_back(compiled.keys[b], request.bodies[b].center);
  double worst = 0;
  for (int s = 0; s <= samples; ++s) {
    const double t = static_cast<double>(s) / samples;
    const std::vector<Eigen::Isometry3d> truth = motion.maps_at(t, request.bodies);
    for (std::size_t b = 0; b < request.bodies.size(); ++b)
      worst = std::max(worst, placement_distance(tracks[b].at(t), truth[b], request.bodies[b].center,
                                                 request.bodies[b].radius));
  }
  return worst;
}

CompileMotionRequest jansen_bodies(const Linkage& linkage, double tolerance) {
  CompileMotionRequest request;
  request.tolerance = tolerance;
  for (const auto& link : linkage.links) {
    AttachedBody body;
    body.attachment = {link[0], link[1], Eigen::Isometry3d(Eigen::Translation3d(0.2, 0.0, 0.05))};
    body.center = Eigen::Vector3d(0.1, 0.02, 0.0);
    body.radius = 0.4;
    request.bodies.push_back(body);
  }
  return request;
}

// The compiled screw keys stay within the tolerance of the true motion everywhere, measured at
// 20,000 times (the keys are chosen by checking 16 times per segment against half of it).
TEST(LinkageMotion, CompiledScrewKeysStayWithinTheToleranceOfTheTrueMotion) {
  const Linkage linkage = test::example("jansen.json");
  const SymbolicKinematics kinematics(linkage, order_joints(linkage));
  const LinkageMotion motion(kinematics, tilted_plane(), 0.0, 2 * kPi);
  std::size_t keys_before = 0;
  for (double tolerance : {1e-3, 1e-4, 1e-5}) {
    SCOPED_TRACE(tolerance);
    const CompileMotionRequest request = jansen_bodies(linkage, tolerance);
    const CompiledMotion compiled = compile_motion(motion, request);
    ASSERT_EQ(compiled.keys.size(), request.bodies.size());
    ASSERT_GE(compiled.times.size(), 2u);
    EXPECT_EQ(compiled.times.front(), 0.0);
    EXPECT_EQ(compiled.times.back(), 1.0);
    for (std::size_t k = 1; k < compiled.times.size(); ++k) EXPECT_LT(compiled.times[k - 1], compiled.times[k]);
    EXPECT_LE(compiled.deviation, tolerance / 2);
    const double measured = dense_deviation(motion, request, compiled, 20000);
    EXPECT_LE(measured, tolerance);
    EXPECT_GT(compiled.times.size(), keys_before);  // a tighter tolerance takes more keys
    keys_before = compiled.times.size();
    std::printf("tolerance %g: %zu keys, deviation at the check times %.3g, measured at 20001 times %.3g\n",
                tolerance, compiled.times.size(), compiled.deviation, measured);
    // The keys are the true motion at their times.
    for (std::size_t k = 0; k < compiled.times.size(); k += 17) {
      const std::vector<Eigen::Isometry3d> truth = motion.maps_at(compiled.times[k], request.bodies);
      for (std::size_t b = 0; b < request.bodies.size(); ++b)
        EXPECT_LT(placement_distance(compiled.keys[b][k].pose.to_isometry(request.bodies[b].center), truth[b],
                                     request.bodies[b].center, request.bodies[b].radius),
                  1e-12);
    }
  }
}

TEST(LinkageMotion, CompilingIsDeterministic) {
  const Linkage linkage = test::example("four_bar_crank_rocker.json");
  const SymbolicKinematics kinematics(linkage, order_joints(linkage));
  const LinkageMotion motion(kinematics, tilted_plane(), 1.0, -2.0);  // clockwise
  const CompileMotionRequest request = jansen_bodies(linkage, 1e-4);
  const CompiledMotion a = compile_motion(motion, request), b = compile_motion(motion, request);
  ASSERT_EQ(a.times, b.times);
  for (std::size_t i = 0; i < a.keys.size(); ++i)
    for (std::size_t k = 0; k < a.keys[i].size(); ++k) {
      EXPECT_EQ(a.keys[i][k].pose.translation, b.keys[i][k].pose.translation);
      EXPECT_EQ(a.keys[i][k].pose.rotation.coeffs(), b.keys[i][k].pose.rotation.coeffs());
    }
  EXPECT_LE(dense_deviation(motion, request, a, 5000), 1e-4);
}

TEST(LinkageMotion, BreakingTheLinkageIsAnInputError) {
  const Linkage linkage = rocker();
  const SymbolicKinematics kinematics(linkage, order_joints(linkage));
  const LinkageMotion motion(kinematics, {}, rad(-130), rad(-60));
  const CompileMotionRequest request = jansen_bodies(linkage, 1e-3);
  try {
    compile_motion(motion, request);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "motor");
    EXPECT_NE(std::string(error.what()).find("cannot be reconstructed at motor angle"), std::string::npos)
        << error.what();
  }
}

TEST(LinkageMotion, MotionsThatNeedTooManyKeysAreInputErrors) {
  const Linkage linkage = test::example("jansen.json");
  const SymbolicKinematics kinematics(linkage, order_joints(linkage));
  const LinkageMotion motion(kinematics, tilted_plane(), 0.0, 2 * kPi);
  for (const auto& [keys, tolerance] : {std::pair{10, 1e-3}, std::pair{50, 1e-4}, std::pair{20000, 1e-16}}) {
    CompileMotionRequest request = jansen_bodies(linkage, tolerance);
    request.max_keys = keys;
    try {
      compile_motion(motion, request);
      ADD_FAILURE() << "expected an InputError for " << keys << " keys, tolerance " << tolerance;
    } catch (const InputError& error) {
      EXPECT_EQ(error.location(), "tolerance") << error.what();
    }
  }
}

}  // namespace
}  // namespace reconfig::linkage
