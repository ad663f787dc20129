// The collision benchmark's baselines (bench/guaranteed_steps.h, bench/fcl_baselines.h): the
// discrete baseline's step really keeps every vertex within the tolerance between samples, and
// FCL's continuous collision finds the first contact where the engine does.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "guaranteed_steps.h"
#include "reconfig/collision/spacetime_detector.h"
#include "reconfig/geometry/primitives.h"
#include "scenes.h"
#ifdef RECONFIG_HAVE_FCL
#include "fcl_baselines.h"
#endif

namespace reconfig {
namespace {

using bench::make_part;

/// A still unit box at the origin and a unit box 0.3 off its axis sliding along x through
/// the polyline `points` (x positions at the given times): they overlap while |x| < 1.
scene::Reconfigurable sliding_boxes(const std::vector<std::pair<double, double>>& points) {
  scene::Reconfigurable scene;
  scene.parts = {make_part("still", geometry::make_box({1, 1, 1})), make_part("moving", geometry::make_box({1, 1, 1}))};
  std::vector<std::pair<double, Eigen::Vector3d>> path;
  for (const auto& [t, x] : points) path.emplace_back(t, Eigen::Vector3d(x, 0.3, 0.2));
  scene::KeyframedTrack track;
  track.translation = bench::polyline_keys(path);
  const motion::Pose start{Eigen::Quaterniond::Identity(), path.front().second}, end{Eigen::Quaterniond::Identity(), path.back().second};
  scene.states = {{"start", {{"moving", start}}}, {"end", {{"moving", end}}}};
  scene.transitions = {bench::one_track_transition("slide", "moving", track)};
  return scene;
}

/// Two parts moving at once: a box turning 180° while it follows a curved Bézier path, and a
/// long bar on a screw track turning 90° about its own end.
scene::Reconfigurable turning_parts() {
  scene::Reconfigurable scene;
  scene.parts = {make_part("box", geometry::make_box({0.5, 0.3, 0.2})), make_part("bar", geometry::make_box({1.2, 0.1, 0.1}))};
  const Eigen::Vector3d a(-1, 0, 0), b(1, 0.5, 0);
  const Eigen::Quaterniond q0 = Eigen::Quaterniond::Identity(), q1(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ()));
  scene::KeyframedTrack box;
  box.translation = {{0.0, a, a, a + Eigen::Vector3d(0.5, 1.0, 0)}, {1.0, b, b + Eigen::Vector3d(-0.5, 0.8, 0.3), b}};
  box.rotation = {{0.0, q0}, {1.0, q1}};
  // The bar turns about its end (0.6 from its center): its center moves on an arc.
  const Eigen::Isometry3d turn = Eigen::Translation3d(0.6, 0, 0) * Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()) *
                                 Eigen::Translation3d(-0.6, 0, 0);
  const Eigen::Vector3d center = scene.parts[1].center;
  scene::ScrewPosesTrack bar;
  bar.poses = {{0.2, motion::Pose{}}, {0.9, motion::Pose::from_isometry(turn, center)}};
  scene.states = {{"start", {{"box", {q0, a}}, {"bar", motion::Pose{}}}},
                  {"end", {{"box", {q1, b}}, {"bar", motion::Pose::from_isometry(turn, center)}}}};
  scene::Transition transition = bench::one_track_transition("turn", "box", box);
  transition.tracks.emplace("bar", bar);
  scene.transitions = {transition};
  return scene;
}

Eigen::MatrixXd world_vertices(const scene::Reconfigurable& scene, int part, double t) {
  const Eigen::Isometry3d M = scene.pose_at(0, part, t).to_isometry(scene.parts[part].center);
  return ((scene.parts[part].mesh.V * M.linear().transpose()).rowwise() + M.translation().transpose()).eval();
}

/// The largest distance any vertex of `part` gets from where it is at time a, over 64 times in [a, b].
double sampled_displacement(const scene::Reconfigurable& scene, int part, double a, double b) {
  const Eigen::MatrixXd start = world_vertices(scene, part, a);
  double largest = 0;
  for (int i = 1; i <= 64; ++i)
    largest = std::max(largest, (world_vertices(scene, part, a + (b - a) * i / 64.0) - start).rowwise().norm().maxCoeff());
  return largest;
}

TEST(GuaranteedSamples, NoVertexMovesMoreThanTheToleranceBetweenTwoSamples) {
  const scene::Reconfigurable scene = turning_parts();
  const double tolerance = 1e-3;
  const bench::GuaranteedSamples samples = bench::guaranteed_samples(scene, 0, tolerance);
  ASSERT_GT(samples.times.size(), 100u);  // the parts move by metres
  EXPECT_EQ(samples.times.front(), 0.0);
  EXPECT_EQ(samples.times.back(), 1.0);
  EXPECT_LE(samples.max_displacement, tolerance);
  double largest = 0;  // over the steps and parts, sampled densely
  for (std::size_t k = 0; k + 1 < samples.times.size(); ++k)
    for (int part = 0; part < 2; ++part) {
      const double moved = sampled_displacement(scene, part, samples.times[k], samples.times[k + 1]);
      ASSERT_LE(moved, tolerance + 1e-12) << "part " << part << ", step " << k;
      largest = std::max(largest, moved);
    }
  // And the step is not needlessly fine: somewhere a vertex does move by most of the tolerance.
  EXPECT_GT(largest, 0.5 * tolerance);
}

TEST(GuaranteedSamples, StepFollowsTheSpeed) {
  // 6 m in one unit of time at constant speed: n = 6 / tolerance, give or take the bound's slack.
  const scene::Reconfigurable scene = sliding_boxes({{0.0, -3.0}, {1.0, 3.0}});
  const bench::GuaranteedSamples samples = bench::guaranteed_samples(scene, 0, 1e-3);
  EXPECT_GE(samples.times.size(), 6001u);
  EXPECT_LE(samples.times.size(), 6200u);
  EXPECT_THROW(bench::guaranteed_samples(scene, 0, 0.0), std::invalid_argument);
}

TEST(GuaranteedSamples, StillSceneNeedsOneStep) {
  scene::Reconfigurable scene = sliding_boxes({{0.0, -3.0}, {1.0, 3.0}});
  scene.transitions[0].tracks.clear();
  EXPECT_EQ(bench::guaranteed_samples(scene, 0, 1e-3).times.size(), 2u);
}

#ifdef RECONFIG_HAVE_FCL
std::vector<collision::CollisionInterval> engine_groups(const scene::Reconfigurable& scene) {
  collision::SpacetimeDetector detector(0, {});
  detector.detect(scene, collision::build_body_trees(scene));
  return detector.groups();
}

TEST(FclContinuous, FirstContactOfTheSlidingBoxIsTheEngines) {
  const scene::Reconfigurable scene = sliding_boxes({{0.0, -3.0}, {1.0, 3.0}});
  const auto groups = engine_groups(scene);
  ASSERT_FALSE(groups.empty());
  const auto intervals = bench::time_intervals_per_pair(groups);
  ASSERT_EQ(intervals.size(), 1u);
  EXPECT_NEAR(intervals[0].t0, 1.0 / 3, 1e-5);
  EXPECT_NEAR(intervals[0].t1, 2.0 / 3, 1e-5);
  const bench::FclParts parts = bench::fcl_parts(scene);
  for (const std::vector<double>& times : {std::vector<double>{0, 1}, std::vector<double>{0, 0.25, 0.5, 0.75, 1}}) {
    const bench::FclCcdResult fcl = bench::fcl_ccd_first_contacts(scene, 0, parts, times);
    ASSERT_FALSE(fcl.contacts.empty()) << times.size() << " samples";
    EXPECT_EQ(fcl.contacts.front().a, 0);
    EXPECT_EQ(fcl.contacts.front().b, 1);
    EXPECT_NEAR(fcl.contacts.front().t, 1.0 / 3, 1e-4);
    EXPECT_NEAR(fcl.contacts.front().t, intervals[0].t0, 1e-4);
    const bench::CcdComparison c = bench::compare_with_engine(fcl.contacts, groups, 1e-4);
    EXPECT_EQ(c.intervals, 1);
    EXPECT_EQ(c.starts_found, 1);
    EXPECT_EQ(c.intervals_missed, 0);
    EXPECT_EQ(c.ends_unreported, 1);  // FCL never says when a collision ends
    EXPECT_EQ(c.pairs_missed, 0);
    EXPECT_EQ(c.extra_contacts, 0);
    EXPECT_LT(c.first_contact_error, 1e-4);
  }
}

TEST(FclContinuous, MissesTheSecondIntervalOfAStep) {
  // The still part is two unit boxes 3 apart (one mesh); the moving box slides from x = -4 to 4
  // through both: collisions over [3/16, 7/16] and [9/16, 13/16], within one step of FCL.
  scene::Reconfigurable scene = sliding_boxes({{0.0, -4.0}, {1.0, 4.0}});
  geometry::Mesh left = geometry::make_box({1, 1, 1}), right = left;
  left.V.col(0).array() -= 1.5;
  right.V.col(0).array() += 1.5;
  geometry::Mesh both;
  both.V.resize(left.V.rows() + right.V.rows(), 3);
  both.V << left.V, right.V;
  both.F.resize(left.F.rows() + right.F.rows(), 3);
  both.F << left.F, (right.F.array() + static_cast<int>(left.V.rows())).matrix();
  scene.parts[0] = make_part("still", both);
  const auto groups = engine_groups(scene);
  const auto intervals = bench::time_intervals_per_pair(groups);
  ASSERT_EQ(intervals.size(), 2u);
  EXPECT_NEAR(intervals[1].t0, 9.0 / 16, 1e-5);
  const bench::FclCcdResult fcl = bench::fcl_ccd_first_contacts(scene, 0, bench::fcl_parts(scene), {0, 1});
  ASSERT_EQ(fcl.contacts.size(), 1u);
  EXPECT_NEAR(fcl.contacts[0].t, 3.0 / 16, 1e-4);
  const bench::CcdComparison c = bench::compare_with_engine(fcl.contacts, groups, 1e-4);
  EXPECT_EQ(c.intervals, 2);
  EXPECT_EQ(c.starts_found, 1);
  EXPECT_EQ(c.starts_missed, 1);
  EXPECT_EQ(c.intervals_missed, 1);
  EXPECT_EQ(c.ends_unreported, 2);
}

TEST(FclDiscrete, SeesTheSlidingBoxesOverlapOnlyInTheMiddle) {
  const scene::Reconfigurable scene = sliding_boxes({{0.0, -3.0}, {1.0, 3.0}});
  const bench::FclParts parts = bench::fcl_parts(scene);
  EXPECT_TRUE(bench::fcl_sample(scene, 0, parts, 0.1, false).pairs.empty());
  const bench::FclSample middle = bench::fcl_sample(scene, 0, parts, 0.5, true);
  ASSERT_EQ(middle.pairs.size(), 1u);
  EXPECT_EQ(middle.pairs[0], std::make_pair(0, 1));
  EXPECT_GT(middle.triangle_pairs, 1);
}
#endif

}  // namespace
}  // namespace reconfig
