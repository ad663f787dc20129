#include "reconfig/collision/reference_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>

#include "reconfig/collision/contact_tolerance.h"
#include "reconfig/collision/triangle_touching.h"
#include "reconfig/geometry/point_in_solid.h"
#include "reconfig/geometry/triangle_intersection.h"
#include "reconfig/scene/scene_file.h"

namespace reconfig::collision {
namespace {

using nlohmann::json;
using scene::Reconfigurable;

Reconfigurable parse(const json& document) {
  return scene::parse_scene(document.dump(), std::filesystem::current_path(), "test.json");
}

json vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

/// A straight, constant-speed Bézier track from a to b (handles at thirds).
json linear_track(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return {{"translation",
           {{{"time", 0}, {"point", vec(a)}, {"in", vec(a)}, {"out", vec(a + (b - a) / 3)}},
            {{"time", 1}, {"point", vec(b)}, {"in", vec(b - (b - a) / 3)}, {"out", vec(b)}}}}};
}

json two_states(const json& start, const json& end) {
  return {{{"name", "start"}, {"poses", start}}, {{"name", "end"}, {"poses", end}}};
}

/// A block slides along x from x = -2 to x = 2 between two static jaws that leave a slot of
/// width `slot` around y = 0; the block is `width` wide. It passes the jaws (|x| ≤ 0.1 + 0.05)
/// for t in [0.4625, 0.5375]: a collision there iff it is wider than the slot.
json slot_scene(double width, double slot) {
  const Eigen::Vector3d a(-2, 0, 0), b(2, 0, 0);
  return {{"format", "reconfig-scene"},
          {"version", 1},
          {"parts",
           {{{"name", "block"}, {"box", {{"size", {0.2, width, 0.2}}}}},
            {{"name", "jaw_low"}, {"box", {{"size", {0.1, 1.0, 0.4}}}}},
            {{"name", "jaw_high"}, {"box", {{"size", {0.1, 1.0, 0.4}}}}}}},
          {"states",
           two_states({{"block", {{"translation", vec(a)}}},
                       {"jaw_low", {{"translation", {0, -0.5 - slot / 2, 0}}}},
                       {"jaw_high", {{"translation", {0, 0.5 + slot / 2, 0}}}}},
                      {{"block", {{"translation", vec(b)}}},
                       {"jaw_low", {{"translation", {0, -0.5 - slot / 2, 0}}}},
                       {"jaw_high", {{"translation", {0, 0.5 + slot / 2, 0}}}}})},
          {"transitions",
           {{{"name", "slide"}, {"from", "start"}, {"to", "end"}, {"tracks", {{"block", linear_track(a, b)}}}}}}};
}

TEST(ReferenceCheck, BlockThroughANarrowSlotCollidesExactlyWhileInside) {
  const Reconfigurable scene = parse(slot_scene(0.3, 0.25));
  ReferenceCheckRequest request;
  request.samples = 801;  // dt = 1/800: the analytic ends 0.4625 and 0.5375 are sample times
  const ReferenceCheckResult result = reference_check(scene, request);
  ASSERT_EQ(result.transitions.size(), 1u);
  const auto& intervals = result.transitions[0].intervals;
  ASSERT_EQ(intervals.size(), 2u);  // block × each jaw
  for (const CollisionInterval& ci : intervals) {
    // Touching at the analytic ends is not a collision: the first and last samples after them.
    EXPECT_NEAR(ci.t0, 0.4625 + 1.0 / 800, 1e-12);
    EXPECT_NEAR(ci.t1, 0.5375 - 1.0 / 800, 1e-12);
    EXPECT_FALSE(ci.containment);
    // The contact region lies in the jaw's slab |x| ≤ 0.05 at the slot's edges.
    EXPECT_GE(ci.box.min().x(), -0.05 - 1e-12);
    EXPECT_LE(ci.box.max().x(), 0.05 + 1e-12);
    EXPECT_LE(std::abs(ci.box.min().y()), 0.15 + 1e-12);
  }
  EXPECT_EQ(intervals[0].parts, (std::vector<int>{0, 1}));
  EXPECT_EQ(intervals[1].parts, (std::vector<int>{0, 2}));
  EXPECT_TRUE(result.any_collision());
  EXPECT_DOUBLE_EQ(result.time_error, 1.0 / 800);
  request.touching_collides = true;  // closed solids: touching counts
  const ReferenceCheckResult closed = reference_check(scene, request);
  for (const CollisionInterval& ci : closed.transitions[0].intervals) {
    EXPECT_NEAR(ci.t0, 0.4625, 1e-12);
    EXPECT_NEAR(ci.t1, 0.5375, 1e-12);
  }
}

TEST(ReferenceCheck, BlockThroughAWideSlotIsFree) {
  const ReferenceCheckResult result = reference_check(parse(slot_scene(0.3, 0.31)));
  EXPECT_FALSE(result.any_collision());
}

/// A 2 m plank turns about z by 170° (slerp: constant angular speed) and sweeps a post of
/// radius r standing at distance d in direction 45°. At angle θ the post touches the plank iff
/// the post's axis is within 0.05 + r of the plank's center line: |sin(θ − 45°)| ≤ (0.05 + r)/d.
TEST(ReferenceCheck, RotatingPlankSweepsAPostAtTheAnalyticAngles) {
  const double r = 0.1, d = 0.7, turn = 170.0 * std::numbers::pi / 180;
  const Eigen::Vector3d post = d * Eigen::Vector3d(std::cos(std::numbers::pi / 4), std::sin(std::numbers::pi / 4), 0);
  const Eigen::Quaterniond end(Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()));
  const json q_end = {end.w(), end.x(), end.y(), end.z()};
  const json document = {
      {"format", "reconfig-scene"},
      {"version", 1},
      {"parts",
       {{{"name", "plank"}, {"box", {{"size", {2.0, 0.1, 0.1}}}}},
        {{"name", "post"}, {"cylinder", {{"radius", r}, {"height", 1.0}}}}}},
      {"states", two_states({{"post", {{"translation", vec(post)}}}},
                            {{"post", {{"translation", vec(post)}}}, {"plank", {{"rotation", q_end}}}})},
      {"transitions",
       {{{"name", "sweep"},
         {"from", "start"},
         {"to", "end"},
         {"tracks",
          {{"plank", {{"rotation", {{{"time", 0}, {"quaternion", {1, 0, 0, 0}}}, {{"time", 1}, {"quaternion", q_end}}}}}}}}}}}};
  ReferenceCheckRequest request;
  request.samples = 1000;
  const ReferenceCheckResult result = reference_check(parse(document), request);
  std::vector<bool> colliding(request.samples, false);
  for (const SampleContact& c : result.contacts[0]) colliding[c.sample] = true;
  // The post is a 48-gon inscribed in the circle: between its apothem and its radius the
  // answer depends on the polygon's phase, so only check samples clear of that band.
  const double apothem = r * std::cos(std::numbers::pi / 48);
  int hits = 0;
  for (int i = 0; i < request.samples; ++i) {
    const double theta = turn * sample_time(i, request.samples);
    const double offset = std::abs(std::sin(theta - std::numbers::pi / 4)) * d;
    const bool facing = std::cos(theta - std::numbers::pi / 4) > 0;
    if (facing && offset < 0.05 + apothem) {
      EXPECT_TRUE(colliding[i]) << "sample " << i;
    }
    if (!facing || offset > 0.05 + r) {
      EXPECT_FALSE(colliding[i]) << "sample " << i;
    }
    hits += colliding[i];
  }
  EXPECT_GT(hits, 0);
  ASSERT_EQ(result.transitions[0].intervals.size(), 1u);
  const double expected_t0 = (std::numbers::pi / 4 - std::asin((0.05 + r) / d)) / turn;
  EXPECT_NEAR(result.transitions[0].intervals[0].t0, expected_t0, 0.01);
}

TEST(ReferenceCheck, APartInsideAnotherIsReported) {
  // A small cube moves from outside into the middle of a big one and stays there.
  const Eigen::Vector3d a(-3, 0, 0), b(0, 0, 0);
  const json document = {
      {"format", "reconfig-scene"},
      {"version", 1},
      {"parts", {{{"name", "big"}, {"box", {{"size", {2, 2, 2}}}}}, {{"name", "small"}, {"box", {{"size", {0.2, 0.2, 0.2}}}}}}},
      {"states", two_states({{"small", {{"translation", vec(a)}}}}, {{"small", {{"translation", vec(b)}}}})},
      {"transitions", {{{"name", "in"}, {"from", "start"}, {"to", "end"}, {"tracks", {{"small", linear_track(a, b)}}}}}}};
  ReferenceCheckRequest request;
  request.samples = 301;  // dt = 1/300
  const ReferenceCheckResult result = reference_check(parse(document), request);
  // Surfaces cross while the small cube crosses x = -1 (x ∈ [-1.1, -0.9] ⇔ t ∈ [19/30, 7/10],
  // touching at 19/30 only); after that it is inside: one interval from the first sample
  // after first contact to the end.
  ASSERT_EQ(result.transitions[0].intervals.size(), 1u);
  const CollisionInterval& ci = result.transitions[0].intervals[0];
  EXPECT_NEAR(ci.t0, 19.0 / 30 + 1.0 / 300, 1e-9);
  EXPECT_EQ(ci.t1, 1.0);
  EXPECT_TRUE(ci.containment);
  int nested = 0;
  for (const SampleContact& c : result.contacts[0]) nested += c.containment;
  EXPECT_EQ(nested, 90);  // samples 211..300: t > 0.7
  ReferenceCheckRequest surface_only = request;
  surface_only.detect_containment = false;
  EXPECT_NEAR(reference_check(parse(document), surface_only).transitions[0].intervals[0].t1, 0.7, 1e-9);
}

/// The BVH-accelerated check agrees with testing every triangle pair of every part pair on
/// random scenes of tumbling boxes and spheres.
TEST(ReferenceCheck, AgreesWithAllPairsBruteForceOnRandomScenes) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(-0.6, 0.6);
  for (int round = 0; round < 6; ++round) {
    json parts = json::array(), start = json::object(), end = json::object(), tracks = json::object();
    for (int p = 0; p < 4; ++p) {
      const std::string name = std::string("p").append(std::to_string(p));  // `"p" + …`: a false -Wrestrict (GCC 12)
      parts.push_back(p % 2 ? json{{"name", name}, {"sphere", {{"radius", 0.25}, }}}
                            : json{{"name", name}, {"box", {{"size", {0.5, 0.3, 0.2}}}}});
      const Eigen::Vector3d a(coordinate(random), coordinate(random), coordinate(random));
      const Eigen::Vector3d b(coordinate(random), coordinate(random), coordinate(random));
      const Eigen::Quaterniond q = Eigen::Quaterniond::UnitRandom();
      start[name] = {{"translation", vec(a)}};
      end[name] = {{"translation", vec(b)}, {"rotation", {q.w(), q.x(), q.y(), q.z()}}};
      json track = linear_track(a, b);
      track["rotation"] = {{{"time", 0}, {"quaternion", {1, 0, 0, 0}}}, {{"time", 1}, {"quaternion", {q.w(), q.x(), q.y(), q.z()}}}};
      tracks[name] = track;
    }
    const Reconfigurable scene = parse({{"format", "reconfig-scene"}, {"version", 1}, {"parts", parts},
                                        {"states", two_states(start, end)},
                                        {"transitions", {{{"name", "t"}, {"from", "start"}, {"to", "end"}, {"tracks", tracks}}}}});
    ReferenceCheckRequest request;
    request.samples = 21;
    request.touching_collides = round % 2 == 0;  // odd rounds: without the pairs that only touch
    const double delta = contact_tolerance(scene, 0);
    const ReferenceCheckResult result = reference_check(scene, request);
    std::map<std::tuple<int, int, int>, int> expected;
    for (int i = 0; i < request.samples; ++i) {
      const double t = sample_time(i, request.samples);
      for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b) {
          const Eigen::MatrixX3d Va = scene.posed_vertices(0, a, t), Vb = scene.posed_vertices(0, b, t);
          const Eigen::MatrixX3i &Fa = scene.parts[a].mesh.F, &Fb = scene.parts[b].mesh.F;
          int pairs = 0;
          for (int f = 0; f < Fa.rows(); ++f)
            for (int g = 0; g < Fb.rows(); ++g) {
              const TriangleCorners ta{Va.row(Fa(f, 0)), Va.row(Fa(f, 1)), Va.row(Fa(f, 2))};
              const TriangleCorners tb{Vb.row(Fb(g, 0)), Vb.row(Fb(g, 1)), Vb.row(Fb(g, 2))};
              pairs += geometry::triangles_intersect(ta[0], ta[1], ta[2], tb[0], tb[1], tb[2]) &&
                       (request.touching_collides || !triangles_touch(ta, tb, delta));
            }
          if (pairs > 0) expected[{i, a, b}] = pairs;
        }
    }
    std::map<std::tuple<int, int, int>, int> found;
    for (const SampleContact& c : result.contacts[0])
      if (!c.containment) found[{c.sample, c.part_a, c.part_b}] = c.triangle_pairs;
    EXPECT_EQ(found, expected) << "round " << round;
  }
}

TEST(ReferenceCheck, ProgressReachesOneAndCancelStops) {
  const Reconfigurable scene = parse(slot_scene(0.3, 0.25));
  double last = 0;
  ReferenceCheckRequest request;
  request.samples = 200;
  request.progress = [&](double f) {
    last = std::max(last, f);
    return true;
  };
  EXPECT_FALSE(reference_check(scene, request).cancelled);
  EXPECT_DOUBLE_EQ(last, 1.0);
  request.progress = [](double) { return false; };
  EXPECT_TRUE(reference_check(scene, request).cancelled);
}

}  // namespace
}  // namespace reconfig::collision
