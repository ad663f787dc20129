#include "reconfig/sweep/swept_volume.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "reconfig/geometry/mass_properties.h"
#include "reconfig/geometry/mesh_check.h"
#include "reconfig/geometry/signed_distance.h"
#include "reconfig/scene/part.h"
#include "support/random_scene.h"

namespace reconfig::sweep {
namespace {

geometry::Mesh box_mesh(const Eigen::Vector3d& size) { return scene::Part::primitive_mesh(scene::BoxPrimitive{size}); }

/// Rigid motion t ↦ rotation by angle·t about z through the origin, then translation·t, with its exact
/// displacement bound for points within `radius` of the origin.
RelativeMotion turn_and_slide(const Eigen::Vector3d& translation, double angle, double radius) {
  return RelativeMotion(
      [=](double t) {
        Eigen::Isometry3d g = Eigen::Isometry3d::Identity();
        g.translate(translation * t).rotate(Eigen::AngleAxisd(angle * t, Eigen::Vector3d::UnitZ()));
        return g;
      },
      [=](double a, double b) { return translation.norm() * (b - a) + radius * std::abs(angle) * (b - a); }, 0, 1);
}

/// Volume of the Minkowski sum of an a×b×c box and a ball of radius r.
double offset_box_volume(const Eigen::Vector3d& s, double r) {
  const double pi = std::numbers::pi;
  return s.prod() + 2 * r * (s.x() * s.y() + s.y() * s.z() + s.z() * s.x()) + pi * r * r * s.sum() + 4.0 / 3 * pi * r * r * r;
}

/// The largest distance from the true swept volume a point of the mesh may have.
double outer_bound(const SweptVolumeResult& result) {
  return result.level + std::sqrt(3.0) * result.grid_step * 1.5;
}

void expect_valid_single_shell(const geometry::Mesh& mesh) {
  const geometry::MeshReport report = geometry::check_mesh(mesh);
  EXPECT_TRUE(report.is_valid_solid()) << report.summary();
  EXPECT_EQ(report.component_count, 1) << report.summary();
}

TEST(SweptVolume, TranslatedBoxIsALongerBox) {
  const Eigen::Vector3d size(0.4, 0.2, 0.1);
  const double epsilon = 0.02;
  SweptVolumeRequest request;
  request.grid_step = 0.01;
  request.offset = epsilon;
  const SweptVolumeResult result =
      swept_volume(box_mesh(size), turn_and_slide({1.0, 0, 0}, 0, size.norm() / 2), request);
  ASSERT_FALSE(result.mesh.empty());
  expect_valid_single_shell(result.mesh);
  const Eigen::Vector3d swept(1.4, 0.2, 0.1);
  const double volume = geometry::mass_properties(result.mesh).volume;
  EXPECT_GE(volume, offset_box_volume(swept, epsilon));
  EXPECT_LE(volume, offset_box_volume(swept, outer_bound(result)));
  const Eigen::Vector3d lo = result.mesh.V.colwise().minCoeff(), hi = result.mesh.V.colwise().maxCoeff();
  const Eigen::Vector3d extent = hi - lo;
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_GE(extent[axis], swept[axis] + 2 * epsilon) << axis;
    EXPECT_LE(extent[axis], swept[axis] + 2 * outer_bound(result)) << axis;
  }
  EXPECT_NEAR(lo.x(), -0.2 - result.level, 2 * result.grid_step);
}

TEST(SweptVolume, BoxTurnedAQuarterAboutItsAxisFillsTheCylinderSector) {
  const Eigen::Vector3d size(0.4, 0.1, 0.1);
  const double epsilon = 0.01, radius = std::hypot(0.2, 0.05);
  SweptVolumeRequest request;
  request.grid_step = 0.008;
  request.offset = epsilon;
  const SweptVolumeResult result =
      swept_volume(box_mesh(size), turn_and_slide(Eigen::Vector3d::Zero(), std::numbers::pi / 2, size.norm() / 2), request);
  expect_valid_single_shell(result.mesh);
  // The rectangle turning from 0° to 90° reaches the circle of its half diagonal along x and y
  // on both sides: the xy extents are that diameter.
  const Eigen::Vector3d extent = result.mesh.V.colwise().maxCoeff() - result.mesh.V.colwise().minCoeff();
  for (int axis = 0; axis < 2; ++axis) {
    EXPECT_GE(extent[axis], 2 * (radius + epsilon)) << axis;
    EXPECT_LE(extent[axis], 2 * (radius + outer_bound(result))) << axis;
  }
  // Volume: the area swept in the plane (two quarter discs of radius ρ between the diagonals'
  // turns plus the rectangle's own area) by Monte Carlo against an exact point test, times height.
  const double alpha = std::atan2(0.05, 0.2);  // the half diagonal's angle
  const auto in_sweep_2d = [&](double x, double y) {
    const double r = std::hypot(x, y);
    if (r > radius) return false;
    for (int k = 0; k <= 2000; ++k) {  // rectangle turned by θ contains (x, y)?
      const double theta = std::numbers::pi / 2 * k / 2000, c = std::cos(theta), s = std::sin(theta);
      const double u = c * x + s * y, v = -s * x + c * y;
      if (std::abs(u) <= 0.2 && std::abs(v) <= 0.05) return true;
    }
    return false;
  };
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-radius, radius);
  int hits = 0;
  const int n = 4000;
  for (int i = 0; i < n; ++i) hits += in_sweep_2d(coordinate(random), coordinate(random));
  const double area = 4 * radius * radius * hits / n;
  EXPECT_GT(area, 0.04 + 0.5 * radius * radius * (std::numbers::pi / 2 - 2 * alpha));  // more than the rectangle
  const double volume = geometry::mass_properties(result.mesh).volume;
  // Between the swept area × height grown by ε... (a lower bound: the prism) and the prism's
  // outer offset (a generous upper bound: the bounding box's offset).
  EXPECT_GE(volume, area * 0.98 * (0.1 + 2 * epsilon));
  EXPECT_LE(volume, offset_box_volume({2 * radius, 2 * radius, 0.1}, outer_bound(result)));
}

/// Every point of B, ε inside its own offset, at random times is inside the swept mesh by at
/// least ε: the mesh bounds the ε-offset of the swept volume. And no point of the mesh lies
/// farther from the swept volume than the documented bound (dense time sampling).
TEST(SweptVolume, ConservativeForRandomPartsAndMotions) {
  for (std::uint32_t seed = 1; seed <= 2; ++seed) {
    testing::RandomSceneOptions options;
    options.parts = 2;
    options.moving = 2;
    options.max_turn = 2.0;
    const scene::Reconfigurable scene = testing::random_scene(seed, options);
    const RelativeMotion motion = relative_motion(scene, 0, 1, 0);
    const geometry::Mesh& part = scene.parts[1].mesh;
    SweptVolumeRequest request;
    request.offset = 0.03;
    request.grid_step = 0.03;
    const SweptVolumeResult result = swept_volume(part, motion, request);
    ASSERT_FALSE(result.mesh.empty()) << seed;
    std::printf("seed %u: verified %d, margin %.3f h\n", seed, int(result.verified), result.margin / result.grid_step);
    expect_valid_single_shell(result.mesh);
    const geometry::MeshSignedDistance swept(result.mesh);
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> time(0, 1);
    double deepest = -1e9;
    for (int i = 0; i < 10000; ++i) {
      const Eigen::Isometry3d g = motion.at(time(random));
      for (int v = 0; v < part.vertex_count(); v += 5)
        deepest = std::max(deepest, swept.query(g * part.V.row(v).transpose()).distance);
    }
    EXPECT_LE(deepest, -request.offset) << seed;
    // Tightness: mesh vertices against the swept distance sampled densely in time.
    const geometry::MeshSignedDistance rest(part);
    std::vector<Eigen::Isometry3d> inverses;
    for (int k = 0; k <= 500; ++k) inverses.push_back(motion.at(k / 500.0).inverse());
    for (int v = 0; v < result.mesh.vertex_count(); v += std::max(1, result.mesh.vertex_count() / 50)) {
      double nearest = 1e9;
      for (const Eigen::Isometry3d& inverse : inverses)
        nearest = std::min(nearest, rest.query(inverse * result.mesh.V.row(v).transpose()).distance);
      EXPECT_LE(nearest, outer_bound(result) + result.motion_error) << "seed " << seed << " vertex " << v;
      EXPECT_GE(nearest, request.offset - 1e-9) << "seed " << seed << " vertex " << v;
    }
  }
}

TEST(SweptVolume, CancelledByProgress) {
  SweptVolumeRequest request;
  request.grid_step = 0.01;
  request.progress = [](double fraction) { return fraction < 0.5; };
  const SweptVolumeResult result =
      swept_volume(box_mesh({0.2, 0.2, 0.2}), turn_and_slide({1, 0, 0}, 1.0, 0.2), request);
  EXPECT_TRUE(result.cancelled);
  EXPECT_TRUE(result.mesh.empty());
}

}  // namespace
}  // namespace reconfig::sweep
