#include "reconfig/resolve/proximity.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "placements.h"
#include "reconfig/collision/detect_collisions.h"
#include "reconfig/collision/reference_check.h"
#include "reconfig/geometry/triangle_closest_points.h"
#include "reconfig/geometry/primitives.h"
#include "reconfig/resolve/interval_energy.h"
#include "resolve_scenes.h"

namespace reconfig::resolve {
namespace {

using geometry::TriangleCorners;
using testing::moved;

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
      best = std::min(best, geometry::triangle_distance(ta, tb));
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
