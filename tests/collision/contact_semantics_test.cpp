// Touching versus interference, and exact interval ends, in the engine and the reference check.

#include <gtest/gtest.h>

#include <random>

#include "reconfig/collision/consolidate.h"
#include "reconfig/collision/contact_tolerance.h"
#include "reconfig/collision/reference_check.h"
#include "reconfig/collision/spacetime_detector.h"
#include "reconfig/collision/triangle_touching.h"
#include "box_scenes.h"

namespace reconfig::collision {
namespace {

using test::boxes;

Eigen::Vector3d normal_of_test(const TriangleCorners& t) { return (t[1] - t[0]).cross(t[2] - t[0]); }

std::vector<CollisionInterval> engine(const scene::Reconfigurable& scene, DetectorOptions options = {}) {
  SpacetimeDetector detector(0, options);
  EXPECT_TRUE(detector.detect(scene, build_body_trees(scene)));
  return consolidate(detector.groups(), detector.containments());
}

std::vector<CollisionInterval> reference(const scene::Reconfigurable& scene, int samples = 601) {
  ReferenceCheckRequest request;
  request.samples = samples;
  return reference_check(scene, request).transitions[0].intervals;
}

TEST(ContactSemantics, ABoxSlidingThroughAnotherCollidesForExactlyTheMiddleThird) {
  // x = −3 + 6t: the boxes' interiors overlap for |x| < 1, t ∈ (1/3, 2/3).
  const scene::Reconfigurable scene = boxes({-3, 0, 0}, {3, 0, 0}, {{0, 0, 0}});
  for (const double frame : {0.01, 0.07, 1.0}) {
    DetectorOptions options;
    options.frame = frame;
    const std::vector<CollisionInterval> intervals = engine(scene, options);
    ASSERT_EQ(intervals.size(), 1u) << "frame " << frame;
    EXPECT_NEAR(intervals[0].t0, 1.0 / 3, 1e-5) << "frame " << frame;
    EXPECT_NEAR(intervals[0].t1, 2.0 / 3, 1e-5) << "frame " << frame;
    EXPECT_LE(intervals[0].t0, 1.0 / 3 + 1e-6);  // outward: never later than the true start
    EXPECT_GE(intervals[0].t1, 2.0 / 3 - 1e-6);
  }
  const std::vector<CollisionInterval> sampled = reference(scene);
  ASSERT_EQ(sampled.size(), 1u);
  EXPECT_NEAR(sampled[0].t0, 1.0 / 3, 1.0 / 600 + 1e-12);
  EXPECT_NEAR(sampled[0].t1, 2.0 / 3, 1.0 / 600 + 1e-12);
}

TEST(ContactSemantics, FaceTouchingBoxesSlideFree) {
  // The mover's face x = 0.5 slides along the fixed box's face x = 0.5.
  const scene::Reconfigurable scene = boxes({1, -3, 0}, {1, 3, 0}, {{0, 0, 0}});
  EXPECT_TRUE(engine(scene).empty());
  EXPECT_TRUE(reference(scene).empty());
  DetectorOptions touching;
  touching.touching_collides = true;  // closed solids: they do touch while side by side
  const std::vector<CollisionInterval> intervals = engine(scene, touching);
  ASSERT_FALSE(intervals.empty());
  EXPECT_NEAR(intervals.front().t0, 1.0 / 3, 1e-3);
  EXPECT_NEAR(intervals.back().t1, 2.0 / 3, 1e-3);
}

TEST(ContactSemantics, TouchingBoxesTurnedByRandomAnglesStayFree) {
  std::mt19937 random(19);
  for (int round = 0; round < 6; ++round) {
    const Eigen::Quaterniond turn = Eigen::Quaterniond::UnitRandom();
    const scene::Reconfigurable scene = boxes({1, -3, 0.25}, {1, 3, -0.25}, {{0, 0, 0}}, turn);
    EXPECT_TRUE(engine(scene).empty()) << "round " << round;
    EXPECT_TRUE(reference(scene, 301).empty()) << "round " << round;
  }
  (void)random;
}

TEST(ContactSemantics, BoxesPressedIntoEachOtherCollide) {
  const scene::Reconfigurable scene = boxes({1 - 1e-3, -3, 0}, {1 - 1e-3, 3, 0}, {{0, 0, 0}});
  const std::vector<CollisionInterval> intervals = engine(scene);
  ASSERT_EQ(intervals.size(), 1u);
  EXPECT_NEAR(intervals[0].t0, 1.0 / 3, 1e-5);
  EXPECT_NEAR(intervals[0].t1, 2.0 / 3, 1e-5);
  const std::vector<CollisionInterval> sampled = reference(scene);
  ASSERT_EQ(sampled.size(), 1u);
  EXPECT_NEAR(sampled[0].t0, 1.0 / 3, 1.0 / 600 + 1e-12);
  EXPECT_NEAR(sampled[0].t1, 2.0 / 3, 1.0 / 600 + 1e-12);
}

TEST(ContactSemantics, AStackOfRestingBoxesIsFree) {
  // Three boxes resting on each other, flush; a fourth slides along the stack's side, touching.
  for (const Eigen::Quaterniond& turn : {Eigen::Quaterniond(1, 0, 0, 0), Eigen::Quaterniond::UnitRandom()}) {
    const scene::Reconfigurable scene = boxes({1, 0, -3}, {1, 0, 3}, {{0, 0, 0}, {0, 0, 1}, {0, 0, 2}}, turn);
    EXPECT_TRUE(engine(scene).empty());
    EXPECT_TRUE(reference(scene, 301).empty());
  }
}

TEST(ContactSemantics, APartInsideAnotherTouchingItsWallCollides) {
  // A small box slides inside a unit box along its floor (touching it), all the time inside.
  const scene::Reconfigurable scene = boxes({-0.2, 0, -0.4}, {0.2, 0, -0.4}, {{0, 0, 0}}, {1, 0, 0, 0}, 0.2);
  const std::vector<CollisionInterval> intervals = engine(scene);
  ASSERT_EQ(intervals.size(), 1u);
  EXPECT_EQ(intervals[0].t0, 0.0);
  EXPECT_EQ(intervals[0].t1, 1.0);
  ASSERT_EQ(reference(scene, 101).size(), 1u);
}

TEST(ContactSemantics, EngineEndsLieWithinTheReferencesOwnError) {
  // Two turned boxes, one sliding straight through the other's neighborhood (the proxy of a
  // straight track is exact, so the engine and the reference see the same motion).
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-0.6, 0.6);
  int compared = 0;
  for (int round = 0; round < 8; ++round) {
    const Eigen::Quaterniond turn = Eigen::Quaterniond::UnitRandom();
    const Eigen::Vector3d from(-3, coordinate(random), coordinate(random)), to(3, coordinate(random), coordinate(random));
    const scene::Reconfigurable scene = boxes(turn.inverse() * from, turn.inverse() * to, {{0, 0, 0}}, turn);
    const std::vector<CollisionInterval> intervals = engine(scene);
    ReferenceCheckRequest request;
    request.samples = 20001;
    const ReferenceCheckResult sampled = reference_check(scene, request);
    const std::vector<CollisionInterval>& expected = sampled.transitions[0].intervals;
    ASSERT_EQ(intervals.size(), expected.size()) << "round " << round;
    for (std::size_t i = 0; i < intervals.size(); ++i) {
      // The reference's first sample lies after the true start by less than its error.
      EXPECT_LE(intervals[i].t0, expected[i].t0 + 1e-6) << "round " << round;
      EXPECT_GE(intervals[i].t0, expected[i].t0 - sampled.time_error - 1e-5) << "round " << round;
      EXPECT_GE(intervals[i].t1, expected[i].t1 - 1e-6) << "round " << round;
      EXPECT_LE(intervals[i].t1, expected[i].t1 + sampled.time_error + 1e-5) << "round " << round;
      ++compared;
    }
  }
  EXPECT_GT(compared, 3);  // most rounds do collide
}

/// `interference_pieces` by its definition: every piece halved where `touching_throughout`
/// cannot certify it, each instant decided on its own.
void halve_by_definition(const TriangleCorners& a0, const TriangleCorners& a1, const TriangleCorners& b0,
                         const TriangleCorners& b1, double lo, double hi, double delta, int depth,
                         std::vector<TimeInterval>& out) {
  const bool ends_interfere = !touching_throughout(a0, a1, b0, b1, lo, lo, delta) &&
                              !touching_throughout(a0, a1, b0, b1, hi, hi, delta);
  if (!ends_interfere && touching_throughout(a0, a1, b0, b1, lo, hi, delta)) return;
  const double mid = 0.5 * (lo + hi);
  if (depth == 0 || ends_interfere || !(lo < mid && mid < hi)) {
    out.push_back({lo, hi});
    return;
  }
  halve_by_definition(a0, a1, b0, b1, lo, mid, delta, depth - 1, out);
  halve_by_definition(a0, a1, b0, b1, mid, hi, delta, depth - 1, out);
}

TEST(TriangleTouching, InterferencePiecesAreThoseOfTheDefinition) {
  // Random triangles passing through, sliding along and resting on a fixed one, as the narrow
  // phase reports their pieces (unmerged, as the traversal asks).
  std::mt19937 random(1919);
  std::uniform_real_distribution<double> unit(-1, 1);
  const auto jitter = [&](double by) -> Eigen::Vector3d { return by * Eigen::Vector3d(unit(random), unit(random), unit(random)); };
  const double delta = 1e-6;
  const TriangleCorners still{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)};
  long pieces = 0, kept = 0, certified = 0, halved = 0;
  for (int round = 0; round < 400; ++round) {
    const int kind = round % 3;  // through, along (in the plane z = 0, facing down), on top (vertex at z = 0)
    TriangleCorners start, end;
    const Eigen::Vector3d shift = Eigen::Vector3d(unit(random), unit(random), kind == 0 ? 2 * unit(random) : 0);
    for (int c = 0; c < 3; ++c) {
      const Eigen::Vector3d corner = kind == 0 ? jitter(0.6) : Eigen::Vector3d(0.5 * unit(random), 0.5 * unit(random), 0);
      start[c] = Eigen::Vector3d(0.3, 0.3, kind == 0 ? 0 : (kind == 2 && c > 0 ? 0.4 : 0)) + corner;
      end[c] = start[c] + shift;
    }
    if (kind == 1 && normal_of_test(start).z() > 0) {  // face down onto the still one
      std::swap(start[1], start[2]);
      std::swap(end[1], end[2]);
    }
    TrianglePairCcdRequest request;
    request.a_start = still;
    request.a_end = still;
    request.b_start = start;
    request.b_end = end;
    request.time_tolerance = 1.0 / 64;
    request.distance_tolerance = 1e-4;
    request.merge_pieces = false;
    const std::vector<TimeInterval> spans = triangle_pair_ccd(request).intervals;
    std::vector<TimeInterval> expected;
    for (const TimeInterval& span : spans) halve_by_definition(still, still, start, end, span.lo, span.hi, delta, 5, expected);
    const std::vector<TimeInterval> found = interference_pieces(still, still, start, end, spans, delta);
    ASSERT_EQ(found.size(), expected.size()) << "round " << round;
    for (std::size_t i = 0; i < found.size(); ++i) {
      EXPECT_EQ(found[i].lo, expected[i].lo) << "round " << round;
      EXPECT_EQ(found[i].hi, expected[i].hi) << "round " << round;
    }
    pieces += static_cast<long>(spans.size());
    kept += static_cast<long>(found.size());
    certified += found.empty() && !spans.empty();
    halved += std::any_of(found.begin(), found.end(), [&](const TimeInterval& f) {
      return std::none_of(spans.begin(), spans.end(), [&](const TimeInterval& s) { return s.lo == f.lo && s.hi == f.hi; });
    });
  }
  EXPECT_GT(pieces, 1000);  // the cases the test is for all occur
  EXPECT_GT(kept, 100);
  EXPECT_GT(certified, 20);
  EXPECT_GT(halved, 20);
}

TEST(TriangleTouching, CoplanarFacesTouchFacingEachOtherAndInterfereFacingTheSameWay) {
  const double delta = 1e-6;
  const TriangleCorners up{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)};  // normal +z
  const TriangleCorners down{Eigen::Vector3d(0.2, 0.2, 0), Eigen::Vector3d(0.2, 0.9, 0), Eigen::Vector3d(0.9, 0.2, 0)};
  EXPECT_TRUE(triangles_touch(up, down, delta));
  const TriangleCorners same{down[0], down[2], down[1]};  // normal +z too
  EXPECT_FALSE(triangles_touch(up, same, delta));
  // Crossing by 1e-3: interference; by δ/2: touching.
  for (const auto& [depth, touch] : {std::pair{1e-3, false}, std::pair{delta / 2, true}}) {
    const TriangleCorners across{Eigen::Vector3d(0.2, 0.2, -depth), Eigen::Vector3d(0.3, 0.2, 1), Eigen::Vector3d(0.2, 0.3, 1)};
    EXPECT_EQ(triangles_touch(up, across, delta), touch) << depth;
  }
}

}  // namespace
}  // namespace reconfig::collision
