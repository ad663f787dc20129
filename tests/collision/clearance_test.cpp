// Clearance: the distance of two triangles and when moving ones come closer than a clearance,
// against dense sampling; clearance intervals of the engine against analytic ends and the
// reference check.

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "box_scenes.h"
#include "reconfig/collision/consolidate.h"
#include "reconfig/collision/contact_tolerance.h"
#include "reconfig/collision/detector_settings.h"
#include "reconfig/collision/reference_check.h"
#include "reconfig/collision/spacetime_detector.h"
#include "reconfig/collision/triangle_clearance.h"
#include "reconfig/scene/edits.h"
#include "reconfig/scene/history.h"

namespace reconfig::collision {
namespace {

using Eigen::Vector3d;
using test::boxes;

TriangleCorners random_triangle(std::mt19937& random, const Vector3d& center, double size) {
  std::uniform_real_distribution<double> coordinate(-size, size);
  TriangleCorners t;
  for (Vector3d& p : t) p = center + Vector3d(coordinate(random), coordinate(random), coordinate(random));
  return t;
}

/// The least distance between points of a fine barycentric grid on each triangle (an upper
/// bound of the true distance, within the grid's spacing of it).
double sampled_distance(const TriangleCorners& a, const TriangleCorners& b, int n) {
  std::vector<Vector3d> pa, pb;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const double u = static_cast<double>(i) / n, v = static_cast<double>(j) / n;
      pa.push_back(a[0] + u * (a[1] - a[0]) + v * (a[2] - a[0]));
      pb.push_back(b[0] + u * (b[1] - b[0]) + v * (b[2] - b[0]));
    }
  double best = std::numeric_limits<double>::infinity();
  for (const Vector3d& p : pa)
    for (const Vector3d& q : pb) best = std::min(best, (p - q).norm());
  return best;
}

double longest_edge(const TriangleCorners& t) {
  return std::max({(t[1] - t[0]).norm(), (t[2] - t[1]).norm(), (t[0] - t[2]).norm()});
}

TEST(TriangleClearance, DistanceMatchesDenseSampling) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> offset(-1.5, 1.5);
  for (int round = 0; round < 40; ++round) {
    const TriangleCorners a = random_triangle(random, Vector3d::Zero(), 1);
    const TriangleCorners b = random_triangle(random, Vector3d(offset(random), offset(random), offset(random)), 1);
    const int n = 40;
    const double sampled = sampled_distance(a, b, n);
    const double exact = geometry::triangle_distance(a, b);
    // The grid's points lie within (longest edge) / n of any point of their triangle.
    EXPECT_LE(exact, sampled + 1e-12) << "round " << round;
    EXPECT_GE(exact, sampled - (longest_edge(a) + longest_edge(b)) / n - 1e-12) << "round " << round;
  }
  // Parallel faces 0.25 apart, and crossing triangles.
  const TriangleCorners floor{Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0)};
  const TriangleCorners above{Vector3d(0.1, 0.1, 0.25), Vector3d(0.5, 0.1, 0.25), Vector3d(0.1, 0.5, 0.25)};
  EXPECT_NEAR(geometry::triangle_distance(floor, above), 0.25, 1e-15);
  const TriangleCorners across{Vector3d(0.2, 0.2, -1), Vector3d(0.3, 0.2, 1), Vector3d(0.2, 0.3, 1)};
  EXPECT_EQ(geometry::triangle_distance(floor, across), 0.0);
}

TEST(TriangleClearance, MovingTrianglesMissNoTimeCloserThanTheClearance) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0, 1);
  int closer_rounds = 0, clear_rounds = 0;
  for (int round = 0; round < 30; ++round) {
    TriangleClearanceRequest request;
    request.a_start = random_triangle(random, Vector3d(-1, 0, 0), 0.5);
    request.a_end = random_triangle(random, Vector3d(1, 0, 0), 0.5);
    request.b_start = random_triangle(random, Vector3d(0, 0.6, 0), 0.5);
    request.b_end = random_triangle(random, Vector3d(0, 0.6, 0), 0.5);
    request.clearance = 0.05 + 0.3 * unit(random);
    request.rounding = 1e-14;
    const TriangleClearanceResult result = triangles_closer_than(request);
    const auto reported = [&](double s) {
      return std::any_of(result.intervals.begin(), result.intervals.end(),
                         [&](const TimeInterval& i) { return s >= i.lo && s <= i.hi; });
    };
    const auto at = [](const TriangleCorners& p0, const TriangleCorners& p1, double s) {
      return TriangleCorners{p0[0] + s * (p1[0] - p0[0]), p0[1] + s * (p1[1] - p0[1]), p0[2] + s * (p1[2] - p0[2])};
    };
    bool any_closer = false;
    for (int k = 0; k <= 2000; ++k) {
      const double s = k / 2000.0;
      const double d = geometry::triangle_distance(at(request.a_start, request.a_end, s), at(request.b_start, request.b_end, s));
      if (d < request.clearance) {
        any_closer = true;
        EXPECT_TRUE(reported(s)) << "round " << round << " s " << s << " distance " << d;
      }
    }
    // A piece longer than the time tolerance was certified closer throughout.
    for (const TimeInterval& piece : result.intervals)
      if (piece.hi - piece.lo > request.time_tolerance)
        for (int k = 0; k <= 20; ++k) {
          const double s = piece.lo + (piece.hi - piece.lo) * k / 20;
          EXPECT_LT(geometry::triangle_distance(at(request.a_start, request.a_end, s), at(request.b_start, request.b_end, s)),
                    request.clearance)
              << "round " << round;
        }
    (any_closer ? closer_rounds : clear_rounds) += 1;
    if (!any_closer) {
      EXPECT_LE(result.intervals.size(), 4u) << "round " << round;  // only near misses, if any
    }
  }
  EXPECT_GT(closer_rounds, 5);  // the oracle does see times closer than the clearance
  EXPECT_GT(clear_rounds, 0);
}

DetectorOptions with_clearance(double clearance) {
  DetectorOptions options;
  options.clearance = clearance;
  return options;
}

std::vector<CollisionInterval> engine(const scene::Reconfigurable& scene, const DetectorOptions& options) {
  SpacetimeDetector detector(0, options);
  EXPECT_TRUE(detector.detect(scene, build_body_trees(scene)));
  return consolidate(detector.intervals(), detector.containments());
}

ReferenceCheckResult reference(const scene::Reconfigurable& scene, double clearance, int samples) {
  ReferenceCheckRequest request;
  request.samples = samples;
  request.clearance = clearance;
  return reference_check(scene, request);
}

long count_clearances(const std::vector<CollisionInterval>& intervals) {
  return std::count_if(intervals.begin(), intervals.end(), [](const CollisionInterval& ci) { return ci.clearance; });
}

TEST(Clearance, BoxesTenDeltaApartViolateTwentyDeltaButNotFive) {
  // The mover slides over the fixed box's top face, 10δ above it.
  const double delta = contact_tolerance(boxes({-3, 0, 1}, {3, 0, 1}, {{0, 0, 0}}), 0);  // the default δ
  const scene::Reconfigurable scene = boxes({-3, 0, 1 + 10 * delta}, {3, 0, 1 + 10 * delta}, {{0, 0, 0}});
  ASSERT_EQ(contact_tolerance(scene, 0), delta);
  const std::vector<CollisionInterval> plain = engine(scene, {});
  EXPECT_TRUE(plain.empty());
  const std::vector<CollisionInterval> near = engine(scene, with_clearance(20 * delta));
  ASSERT_EQ(near.size(), 1u);
  EXPECT_TRUE(near[0].clearance);
  EXPECT_FALSE(near[0].containment);
  // Closer than 20δ while |x| < 1 + √300 δ.
  EXPECT_NEAR(near[0].t0, (2 - std::sqrt(300.0) * delta) / 6, 1e-5);
  EXPECT_NEAR(near[0].t1, (4 + std::sqrt(300.0) * delta) / 6, 1e-5);
  EXPECT_TRUE(engine(scene, with_clearance(5 * delta)).empty());
  const ReferenceCheckResult sampled = reference(scene, 20 * delta, 601);
  ASSERT_EQ(sampled.transitions[0].intervals.size(), 1u);
  EXPECT_TRUE(sampled.transitions[0].intervals[0].clearance);
  EXPECT_NEAR(sampled.transitions[0].intervals[0].t0, near[0].t0, sampled.time_error + 1e-5);
  EXPECT_NEAR(sampled.transitions[0].intervals[0].t1, near[0].t1, sampled.time_error + 1e-5);
  EXPECT_TRUE(reference(scene, 5 * delta, 601).transitions[0].intervals.empty());
}

TEST(Clearance, ASlidingBoxsClearanceEndsMatchTheAnalyticOnes) {
  // Gap g above the fixed box's top face, clearance C: the edges' horizontal gap h gives the
  // distance √(h² + g²), so the parts are closer than C while |x| < 1 + √(C² − g²), x = −3 + 6t.
  const double g = 0.01;
  for (const double clearance : {0.015, 0.02, 0.05}) {
    const scene::Reconfigurable scene = boxes({-3, 0, 1 + g}, {3, 0, 1 + g}, {{0, 0, 0}});
    for (const double frame : {0.01, 0.07}) {
      DetectorOptions options = with_clearance(clearance);
      options.frame = frame;
      const std::vector<CollisionInterval> intervals = engine(scene, options);
      ASSERT_EQ(intervals.size(), 1u) << clearance;
      const double s = std::sqrt(clearance * clearance - g * g);
      EXPECT_NEAR(intervals[0].t0, (2 - s) / 6, 1e-5) << clearance << " frame " << frame;
      EXPECT_NEAR(intervals[0].t1, (4 + s) / 6, 1e-5) << clearance << " frame " << frame;
      EXPECT_LE(intervals[0].t0, (2 - s) / 6 + 1e-6);  // outward: never later than the true start
      EXPECT_GE(intervals[0].t1, (4 + s) / 6 - 1e-6);
    }
  }
}

TEST(Clearance, ACollisionIsNoClearanceIntervalButTheApproachIs) {
  // Sliding through: closer than C just before and after the middle third, colliding within it.
  const double clearance = 0.05;
  const scene::Reconfigurable scene = boxes({-3, 0, 0}, {3, 0, 0}, {{0, 0, 0}});
  const std::vector<CollisionInterval> intervals = engine(scene, with_clearance(clearance));
  ASSERT_EQ(intervals.size(), 3u);
  EXPECT_TRUE(intervals[0].clearance);
  EXPECT_FALSE(intervals[1].clearance);
  EXPECT_TRUE(intervals[2].clearance);
  EXPECT_NEAR(intervals[0].t0, (2 - clearance) / 6, 1e-5);
  EXPECT_NEAR(intervals[0].t1, 1.0 / 3, 1e-5);
  EXPECT_NEAR(intervals[1].t0, 1.0 / 3, 1e-5);
  EXPECT_NEAR(intervals[1].t1, 2.0 / 3, 1e-5);
  EXPECT_NEAR(intervals[2].t0, 2.0 / 3, 1e-5);
  EXPECT_NEAR(intervals[2].t1, (4 + clearance) / 6, 1e-5);
}

TEST(Clearance, TouchingBoxesAreWithinTheClearanceUnlessTouchingCollides) {
  const scene::Reconfigurable scene = boxes({1, -3, 0}, {1, 3, 0}, {{0, 0, 0}});
  const std::vector<CollisionInterval> touching = engine(scene, with_clearance(0.01));
  ASSERT_FALSE(touching.empty());
  EXPECT_EQ(count_clearances(touching), static_cast<long>(touching.size()));
  DetectorOptions closed = with_clearance(0.01);
  closed.touching_collides = true;
  const std::vector<CollisionInterval> colliding = engine(scene, closed);
  ASSERT_FALSE(colliding.empty());
  EXPECT_LT(count_clearances(colliding), static_cast<long>(colliding.size()));
}

TEST(Clearance, RandomTwoPartScenesAgreeWithTheReference) {
  std::mt19937 random(23);
  std::uniform_real_distribution<double> coordinate(-1.2, 1.2);
  long clearances = 0;
  for (int round = 0; round < 6; ++round) {
    const Eigen::Quaterniond turn = Eigen::Quaterniond::UnitRandom();
    const Vector3d from(-3, coordinate(random), coordinate(random)), to(3, coordinate(random), coordinate(random));
    const scene::Reconfigurable scene = boxes(turn.inverse() * from, turn.inverse() * to, {{0, 0, 0}}, turn);
    const double clearance = 0.1;
    const std::vector<CollisionInterval> intervals = engine(scene, with_clearance(clearance));
    const ReferenceCheckResult sampled = reference(scene, clearance, 6001);
    const std::vector<CollisionInterval>& expected = sampled.transitions[0].intervals;
    ASSERT_EQ(intervals.size(), expected.size()) << "round " << round;
    for (std::size_t i = 0; i < intervals.size(); ++i) {
      EXPECT_EQ(intervals[i].clearance, expected[i].clearance) << "round " << round;
      // The reference's first sample lies after the true start by less than its error; where a
      // clearance interval ends at a collision the two share that end.
      EXPECT_NEAR(intervals[i].t0, expected[i].t0, sampled.time_error + 1e-5) << "round " << round;
      EXPECT_NEAR(intervals[i].t1, expected[i].t1, sampled.time_error + 1e-5) << "round " << round;
      clearances += intervals[i].clearance ? 1 : 0;
    }
  }
  EXPECT_GT(clearances, 3);  // most rounds come close
}

TEST(Clearance, AnUpdateGivesTheClearancesOfADetectionFromScratch) {
  // The mover slides 0.01 above the fixed box and through a second one; a key added in the
  // middle of its track, then moved, changes its motion there only.
  scene::Reconfigurable scene = boxes({-3, 0, 1.01}, {3, 0, 1.01}, {{0, 0, 0}, {0, 0, 1.6}});
  const BodyTrees trees = build_body_trees(scene);
  const DetectorOptions options = with_clearance(0.02);
  SpacetimeDetector incremental(0, options);
  ASSERT_TRUE(incremental.detect(scene, trees));
  ASSERT_GT(count_clearances(incremental.intervals()), 0);  // the test is about them
  scene::History history;
  ASSERT_TRUE(incremental.update(scene, trees, history.execute(scene, scene::insert_key("slide", "mover", scene::KeyKind::kTranslation, 0.5))));
  for (const double lift : {0.005, 0.3, -0.004}) {
    const auto& keys = std::get<scene::KeyframedTrack>(scene.transitions[0].tracks.at("mover")).translation;
    motion::TranslationKey moved = keys[1];
    moved.point.z() += lift;
    moved.in.z() += lift;
    moved.out.z() += lift;
    ASSERT_TRUE(incremental.update(scene, trees, history.execute(scene, scene::set_translation_key("slide", "mover", 1, moved))));
    SpacetimeDetector fresh(0, options);
    ASSERT_TRUE(fresh.detect(scene, trees));
    const std::vector<CollisionInterval> updated = consolidate(incremental.intervals(), incremental.containments());
    const std::vector<CollisionInterval> expected = consolidate(fresh.intervals(), fresh.containments());
    ASSERT_EQ(updated.size(), expected.size()) << "lift " << lift;
    for (std::size_t i = 0; i < updated.size(); ++i) {
      EXPECT_EQ(updated[i].clearance, expected[i].clearance) << "lift " << lift;
      EXPECT_EQ(updated[i].t0, expected[i].t0) << "lift " << lift;
      EXPECT_EQ(updated[i].t1, expected[i].t1) << "lift " << lift;
      EXPECT_EQ(updated[i].box.min(), expected[i].box.min()) << "lift " << lift;
      EXPECT_EQ(updated[i].box.max(), expected[i].box.max()) << "lift " << lift;
    }
    for (std::size_t p = 0; p < fresh.proxies().size(); ++p)
      EXPECT_EQ(incremental.proxies()[p].times, fresh.proxies()[p].times) << "lift " << lift;
  }
}

TEST(Clearance, TheSceneSettingTurnsItOn) {
  const scene::Reconfigurable scene =
      boxes({-3, 0, 1.01}, {3, 0, 1.01}, {{0, 0, 0}}, {1, 0, 0, 0}, 1, {{"clearance", 0.02}});
  ASSERT_TRUE(scene.collision.clearance);
  EXPECT_EQ(*scene.collision.clearance, 0.02);
  const DetectorOptions options = with_settings({}, scene.collision);
  EXPECT_EQ(options.clearance, 0.02);
  EXPECT_EQ(settings_of(options).clearance, 0.02);
  const std::vector<CollisionInterval> intervals = engine(scene, options);
  ASSERT_EQ(intervals.size(), 1u);
  EXPECT_TRUE(intervals[0].clearance);
  EXPECT_THROW(boxes({-3, 0, 1.01}, {3, 0, 1.01}, {{0, 0, 0}}, {1, 0, 0, 0}, 1, {{"clearance", -1}}), std::exception);
}

}  // namespace
}  // namespace reconfig::collision
