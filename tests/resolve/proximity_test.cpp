#include "reconfig/resolve/proximity.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "placements.h"
#include "reconfig/collision/detect_collisions.h"
#include "reconfig/collision/reference_check.h"
#include "reconfig/collision/triangle_clearance.h"
#include "reconfig/geometry/primitives.h"
#include "reconfig/resolve/interval_energy.h"
#include "resolve/detail/triangle_closest_points.h"
#include "resolve_scenes.h"

namespace reconfig::resolve {
namespace {

using detail::TriangleCorners;
using testing::moved;

TriangleCorners random_triangle(testing::RandomPlacements& random, const Eigen::Vector3d& around) {
  return {around + random.vector(), around + random.vector(), around + random.vector()};
}

/// Slow reference: the least distance between points of a dense barycentric grid on each.
double sampled_distance(const TriangleCorners& a, const TriangleCorners& b, int n) {
  std::vector<Eigen::Vector3d> pa, pb;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const double u = double(i) / n, v = double(j) / n;
      pa.push_back(a[0] + u * (a[1] - a[0]) + v * (a[2] - a[0]));
      pb.push_back(b[0] + u * (b[1] - b[0]) + v * (b[2] - b[0]));
    }
  double best = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& p : pa)
    for (const Eigen::Vector3d& q : pb) best = std::min(best, (p - q).norm());
  return best;
}

/// Whether p lies in triangle t (within `eps` of its plane and inside its edges).
bool in_triangle(const Eigen::Vector3d& p, const TriangleCorners& t, double eps) {
  const Eigen::Vector3d n = (t[1] - t[0]).cross(t[2] - t[0]);
  if (std::abs(n.normalized().dot(p - t[0])) > eps) return false;
  for (int k = 0; k < 3; ++k)
    if (n.dot((t[(k + 1) % 3] - t[k]).cross(p - t[k])) < -eps * n.norm()) return false;
  return true;
}

TEST(TriangleClosestPoints, MatchesDenseSamplingOnRandomPairs) {
  testing::RandomPlacements random(3);
  for (int trial = 0; trial < 100; ++trial) {
    const TriangleCorners a = random_triangle(random, Eigen::Vector3d::Zero());
    const TriangleCorners b = random_triangle(random, 1.5 * random.vector());
    const detail::TriangleClosestPoints c = detail::triangle_closest_points(a, b);
    // The sampled distance is at least the true one, and within the grid's spacing of it.
    const double sampled = sampled_distance(a, b, 30);
    double longest = 0;
    for (int k = 0; k < 3; ++k) longest = std::max({longest, (a[k] - a[(k + 1) % 3]).norm(), (b[k] - b[(k + 1) % 3]).norm()});
    EXPECT_LE(c.distance, sampled + 1e-12) << trial;
    EXPECT_GE(c.distance, sampled - 2 * longest / 30) << trial;
    EXPECT_NEAR(c.distance, collision::triangle_distance(a, b), 1e-12) << trial;
    if (c.distance > 0) {
      EXPECT_NEAR((c.on_a - c.on_b).norm(), c.distance, 1e-12) << trial;
      EXPECT_TRUE(in_triangle(c.on_a, a, 1e-9)) << trial;
      EXPECT_TRUE(in_triangle(c.on_b, b, 1e-9)) << trial;
    }
    EXPECT_NEAR(detail::triangle_closest_points(b, a).distance, c.distance, 1e-12) << trial;  // symmetric
  }
}

TEST(TriangleClosestPoints, CrossingTouchingAndDegenerateTrianglesAreDefined) {
  const TriangleCorners a = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)};
  // Piercing through the middle (no vertex or edge pair at distance 0): still 0.
  const TriangleCorners pierce = {Eigen::Vector3d(0.2, 0.2, -1), Eigen::Vector3d(0.3, 0.2, 1), Eigen::Vector3d(0.25, 3, 1)};
  EXPECT_EQ(detail::triangle_closest_points(a, pierce).distance, 0.0);
  // Coplanar, overlapping.
  const TriangleCorners coplanar = {Eigen::Vector3d(0.1, 0.1, 0), Eigen::Vector3d(2, 0.1, 0), Eigen::Vector3d(0.1, 2, 0)};
  EXPECT_EQ(detail::triangle_closest_points(a, coplanar).distance, 0.0);
  // A vertex 1e-7 above the face: exactly that far.
  const TriangleCorners above = {Eigen::Vector3d(0.2, 0.2, 1e-7), Eigen::Vector3d(0.2, 0.3, 1), Eigen::Vector3d(0.3, 0.2, 1)};
  EXPECT_NEAR(detail::triangle_closest_points(a, above).distance, 1e-7, 1e-15);
  // Collapsed to a point and to a segment: finite.
  const TriangleCorners point = {Eigen::Vector3d(2, 2, 2), Eigen::Vector3d(2, 2, 2), Eigen::Vector3d(2, 2, 2)};
  const TriangleCorners segment = {Eigen::Vector3d(3, 0, 1), Eigen::Vector3d(-3, 0, 1), Eigen::Vector3d(0, 0, 1)};
  EXPECT_NEAR(detail::triangle_closest_points(a, point).distance, (Eigen::Vector3d(2, 2, 2) - Eigen::Vector3d(0.5, 0.5, 0)).norm(), 1e-12);
  EXPECT_NEAR(detail::triangle_closest_points(a, segment).distance, 1.0, 1e-12);
  EXPECT_NEAR(detail::triangle_closest_points(point, segment).distance, (Eigen::Vector3d(2, 2, 2) - Eigen::Vector3d(2, 0, 1)).norm(), 1e-12);
}

/// Slow reference: the least distance over all triangle pairs.
double brute_force_distance(const geometry::Mesh& a, const Eigen::Isometry3d& pa, const geometry::Mesh& b,
                            const Eigen::Isometry3d& pb) {
  double best = std::numeric_limits<double>::infinity();
  for (int f = 0; f < a.face_count(); ++f)
    for (int g = 0; g < b.face_count(); ++g) {
      TriangleCorners ta, tb;
      for (int k = 0; k < 3; ++k) {
        ta[k] = pa * Eigen::Vector3d(a.V.row(a.F(f, k)));
        tb[k] = pb * Eigen::Vector3d(b.V.row(b.F(g, k)));
      }
      best = std::min(best, collision::triangle_distance(ta, tb));
    }
  return best;
}

TEST(Proximity, MatchesAllTrianglePairsOnRandomPlacements) {
  testing::RandomPlacements random(5);
  const geometry::Mesh ma = geometry::make_sphere(0.5, 1), mb = geometry::make_box({1, 0.4, 0.6});
  const PartShape a(ma), b(mb);
  const double reach = 0.3;
  int near = 0, far = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const Eigen::Isometry3d pa = random.near_origin(0.8), pb = random.near_origin(0);
    const Proximity p = proximity(a, pa, b, pb, reach);
    const double d = brute_force_distance(ma, pa, mb, pb);
    if (d < reach) {
      ++near;
      EXPECT_NEAR(p.distance, d, 1e-12) << trial;
      EXPECT_NEAR(p.deficit, reach - d, 1e-12) << trial;
      if (d > 0) {
        EXPECT_NEAR((p.nearest_a - p.nearest_b).norm(), d, 1e-12) << trial;
      }
    } else {
      ++far;
      EXPECT_EQ(p.deficit, 0.0) << trial;
      EXPECT_EQ(p.distance, reach) << trial;
    }
    EXPECT_GE(p.deficit, 0.0);
    EXPECT_LE(p.deficit, reach);
  }
  EXPECT_GT(near, 10);
  EXPECT_GT(far, 5);
}

TEST(Proximity, GradientMatchesFiniteDifferences) {
  testing::RandomPlacements random(11);
  const PartShape a(geometry::make_sphere(0.5, 2)), b(geometry::make_box({1, 0.5, 0.7}));
  const double reach = 0.4;
  int checked = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const Eigen::Isometry3d pa = random.near_origin(1.0), pb = random.near_origin(0);
    const Proximity p = proximity(a, pa, b, pb, reach);
    if (p.distance <= 1e-3 || p.distance >= reach - 1e-3) continue;  // apart, within reach
    const Eigen::Vector3d v = random.vector(), w = random.vector();
    const double h = 1e-7;
    const double fd =
        (proximity(a, moved(pa, v, w, h), b, pb, reach).deficit - proximity(a, moved(pa, v, w, -h), b, pb, reach).deficit) /
        (2 * h);
    EXPECT_NEAR(p.gradient.force.dot(v) + p.gradient.torque.dot(w), fd, 1e-5 * (1 + std::abs(fd))) << trial;
    // Moving a a little against the gradient widens the gap.
    const Eigen::Vector3d f = p.gradient.force, t = p.gradient.torque;
    EXPECT_LT(proximity(a, moved(pa, -f, -t, 1e-4), b, pb, reach).deficit, p.deficit) << trial;
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

/// A box orbiting a still cylinder (48 sides, radius 1) about its axis, its inner face 1e-5
/// outside the cylinder's corners: the true parts never meet, but the detector's proxy of the
/// orbiting box moves its vertices on chords, which cut up to the tolerance toward the axis —
/// the proxies interfere, as the kitchen's door and bin did, with no contour and no point
/// inside to measure.
scene::Reconfigurable orbiting_box_scene() {
  constexpr double gap = 1e-5;
  geometry::Mesh box = geometry::make_box({0.2, 0.2, 0.2});
  box.V.col(0).array() += 1 + gap + 0.1;
  scene::Reconfigurable scene;
  scene.parts = {testing::make_part("post", geometry::make_cylinder(1, 0.6)), testing::make_part("orbiter", box)};
  const Eigen::Vector3d c = scene.parts[1].center;
  const Eigen::Quaterniond quarter(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  const motion::Pose end{quarter, quarter * c - c};  // a quarter turn about the z axis
  scene::ScrewPosesTrack track;
  track.poses = {{0.0, motion::Pose{}}, {1.0, end}};
  scene.states = {{"start", {}}, {"end", {{"orbiter", end}}}};
  scene.transitions.push_back({"orbit", "start", "end", true, {{"orbiter", track}}});
  return scene;
}

TEST(Proximity, ANearMissTheDetectorReportsHasAnEnergyThatLeadsOut) {
  const scene::Reconfigurable scene = orbiting_box_scene();
  collision::CollisionRequest request;
  const collision::CollisionResult detected = collision::detect_collisions(scene, request);
  ASSERT_FALSE(detected.transitions.empty());
  const std::vector<collision::CollisionInterval>& intervals = detected.transitions[0].intervals;
  ASSERT_FALSE(intervals.empty());  // the detector reports interference...
  EXPECT_FALSE(intervals[0].clearance);
  EXPECT_FALSE(collision::reference_check(scene, {}).any_collision());  // ...the true motion has none
  ShapeCache shapes;
  for (const collision::CollisionInterval& ci : intervals) {
    // Without the proximity term the energy is blind to it.
    const IntervalEnergy blind = interval_energy(scene, shapes, 0, ci, 0.01, -1, 0.0);
    EXPECT_EQ(blind.energy, 0.0);
    const IntervalEnergy energy = interval_energy(scene, shapes, 0, ci);
    EXPECT_GT(energy.energy, 0.0);
    EXPECT_EQ(energy.energy, energy.proximity_energy);
    // Every sample sees the deficit, and moving the orbiter (part b) away from the axis
    // lowers it: the gradient of part a (the post) points toward the orbiter.
    ASSERT_EQ(energy.pairs.size(), 1u);
    for (const EnergySample& s : energy.pairs[0].second.samples) {
      EXPECT_GT(s.proximity, 0.0) << s.time;
      const Eigen::Isometry3d orbiter = scene.pose_at(0, 1, s.time).to_isometry(scene.parts[1].center);
      const Eigen::Vector3d outward = (orbiter * scene.parts[1].center).normalized();
      EXPECT_GT(s.gradient.force.dot(outward), 0.5) << s.time;  // |∂D/∂x| = 1
    }
  }
}

}  // namespace
}  // namespace reconfig::resolve
