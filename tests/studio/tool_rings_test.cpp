// The sculpt tool's rings (tool_rings.h): the turn a drag sweeps on screen, and which ring a
// screen point is on, against the 3D rotations they stand for and a dense sampling.

#include "tool_rings.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <random>
#include <vector>

#include "gizmo.h"
#include "random_camera.h"
#include "reconfig/view/picking.h"

namespace reconfig::studio {
namespace {

constexpr int kWidth = 800, kHeight = 600;

Eigen::Vector2d pixel(const view::Camera& camera, const Eigen::Vector3d& point) {
  const auto projected = view::project_to_pixel(camera, kWidth, kHeight, point);
  EXPECT_TRUE(projected.has_value());
  return projected ? projected->pixel : Eigen::Vector2d::Zero();
}

Eigen::Matrix3d random_axes(std::mt19937& random) {
  std::normal_distribution<double> n;
  return Eigen::Quaterniond(n(random), n(random), n(random), n(random)).normalized().toRotationMatrix();
}

/// Ring `axis`'s point at angle `a` (from the ring's first point, right-handed about the axis).
Eigen::Vector3d on_ring(const ToolRings& rings, int axis, double a) {
  return rings.center + Eigen::AngleAxisd(a, rings.axes.col(axis)) * (rings.ring(axis).front() - rings.center);
}

// Oracle: a ring facing the camera projects to a circle (a plane parallel to the image plane
// maps by a similarity), so the swept turn is the 3D angle turned, either way round.
TEST(ToolRings, ARingFacingTheViewerSweepsTheAngleTurned) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-0.3, 0.3), angle(-3, 3);
  for (int trial = 0; trial < 200; ++trial) {
    const view::Camera camera = random_camera(random);
    const double towards = trial % 2 ? 1 : -1;  // the axis pointing at the viewer or away
    Eigen::Matrix3d axes;
    axes.col(2) = towards * camera.forward();
    axes.col(0) = axes.col(2).unitOrthogonal();
    axes.col(1) = axes.col(2).cross(axes.col(0));
    const Eigen::Vector3d center = camera.target + Eigen::Vector3d(u(random), u(random), u(random));
    const ToolRings rings = ToolRings::around(camera, kHeight, center, axes, 0);
    const double a = angle(random), b = angle(random);
    const double turn = swept_turn(pixel(camera, rings.center), pixel(camera, on_ring(rings, 2, a)),
                                   pixel(camera, on_ring(rings, 2, b)), axes.col(2), camera.forward());
    EXPECT_NEAR(std::remainder(turn - (b - a), 2 * M_PI), 0, 1e-9) << "trial " << trial;
  }
}

// Oracle: whatever the ring's slant, a ring point turned once round the axis in small steps
// sweeps +2π round the projected center, every step the right way round.
TEST(ToolRings, ATurnRoundAnySlantedRingSweepsOneTurnTheRightWay) {
  std::mt19937 random(12);
  for (int trial = 0; trial < 100; ++trial) {
    const view::Camera camera = random_camera(random);
    const ToolRings rings = ToolRings::around(camera, kHeight, camera.target, random_axes(random), 0);
    for (int axis = 0; axis < 3; ++axis) {
      if (std::abs(rings.axes.col(axis).dot(camera.forward())) < 0.05) continue;  // seen edge-on
      double total = 0;
      for (int step = 0; step < 90; ++step) {
        const Eigen::Vector2d from = pixel(camera, on_ring(rings, axis, step * 2 * M_PI / 90)),
                              to = pixel(camera, on_ring(rings, axis, (step + 1) * 2 * M_PI / 90));
        const double turn = swept_turn(pixel(camera, rings.center), from, to, rings.axes.col(axis), camera.forward());
        EXPECT_GT(turn, 0) << "trial " << trial << " axis " << axis << " step " << step;
        total += turn;
      }
      EXPECT_NEAR(total, 2 * M_PI, 1e-9) << "trial " << trial << " axis " << axis;
    }
  }
  EXPECT_EQ(swept_turn({1, 1}, {1, 1}, {2, 1}, Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX()), 0);
}

// Oracle: the ring `hit` names is the one a dense sampling of the rings not seen edge-on
// finds nearest, and nothing beyond the tolerance (cases within half a pixel of a tie or the tolerance are
// left out: the 64-gon is within 0.1 pixel of the ring here, the samples 0.4 pixel apart).
TEST(ToolRings, HitIsTheNearestRingWithinTheTolerance) {
  std::mt19937 random(13);
  std::uniform_real_distribution<double> offset(-120, 120);
  int hits = 0, misses = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const view::Camera camera = random_camera(random);
    const ToolRings rings = ToolRings::around(camera, kHeight, camera.target, random_axes(random), 0);
    const Eigen::Vector2d center = pixel(camera, rings.center);
    std::array<std::vector<Eigen::Vector2d>, 3> samples;
    for (int axis = 0; axis < 3; ++axis)
      for (int i = 0; i < 1024; ++i) samples[axis].push_back(pixel(camera, on_ring(rings, axis, i * 2 * M_PI / 1024)));
    for (int probe = 0; probe < 20; ++probe) {
      const Eigen::Vector2d mouse = center + Eigen::Vector2d(offset(random), offset(random));
      std::array<double, 3> distance{INFINITY, INFINITY, INFINITY};
      for (int axis = 0; axis < 3; ++axis)
        for (const Eigen::Vector2d& sample : samples[axis])
          if (!rings.edge_on(camera, axis)) distance[axis] = std::min(distance[axis], (sample - mouse).norm());
      const int nearest = static_cast<int>(std::min_element(distance.begin(), distance.end()) - distance.begin());
      std::array<double, 3> others = distance;
      others[nearest] = INFINITY;
      const double second = *std::min_element(others.begin(), others.end());
      const std::optional<int> hit = rings.hit(camera, kWidth, kHeight, mouse);
      if (distance[nearest] < 7 - 0.5 && second > distance[nearest] + 0.5) {
        EXPECT_EQ(hit, nearest) << "trial " << trial;
        ++hits;
      } else if (distance[nearest] > 7 + 0.5) {
        EXPECT_FALSE(hit) << "trial " << trial;
        ++misses;
      }
    }
  }
  EXPECT_GT(hits, 60);
  EXPECT_GT(misses, 300);
}

// A ring seen edge-on is a line through the center on screen: it is never picked there, so a
// press on the tool's center still moves the tool.
TEST(ToolRings, RingsSeenEdgeOnAreNotPicked) {
  view::Camera camera;
  camera.yaw = 0;
  camera.pitch = 0;
  const ToolRings rings = ToolRings::around(camera, kHeight, camera.target, Eigen::Matrix3d::Identity(), 0);
  const Eigen::Vector3d sight = (rings.center - camera.eye()).normalized();
  for (int axis = 0; axis < 3; ++axis)
    EXPECT_EQ(rings.edge_on(camera, axis), std::abs(sight.dot(Eigen::Vector3d::Unit(axis))) < 0.2) << axis;
  EXPECT_FALSE(rings.hit(camera, kWidth, kHeight, pixel(camera, rings.center)));
  Eigen::Index facing = 0;
  sight.cwiseAbs().maxCoeff(&facing);  // the ring facing the camera most
  EXPECT_EQ(rings.hit(camera, kWidth, kHeight, pixel(camera, rings.ring(static_cast<int>(facing))[7])), facing);
}

TEST(ToolRings, TheyAreTheGizmosSizeOnScreenOrEncloseABiggerTool) {
  std::mt19937 random(14);
  const view::Camera camera = random_camera(random);
  const double gizmo = Gizmo::sized_for(camera, kHeight, camera.target).ring_radius;
  EXPECT_EQ(ToolRings::around(camera, kHeight, camera.target, Eigen::Matrix3d::Identity(), 0).radius, gizmo);
  EXPECT_EQ(ToolRings::around(camera, kHeight, camera.target, Eigen::Matrix3d::Identity(), gizmo).radius, 1.1 * gizmo);
  // Each ring lies in the plane of the two other axes, at the radius.
  const ToolRings rings = ToolRings::around(camera, kHeight, camera.target, random_axes(random), 0);
  for (int axis = 0; axis < 3; ++axis)
    for (const Eigen::Vector3d& point : rings.ring(axis)) {
      EXPECT_NEAR((point - rings.center).norm(), rings.radius, 1e-12);
      EXPECT_NEAR((point - rings.center).dot(rings.axes.col(axis)), 0, 1e-12);
    }
}

}  // namespace
}  // namespace reconfig::studio
