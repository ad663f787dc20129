#include "reconfig/sculpt/tool.h"

#include <gtest/gtest.h>

#include <random>

#include "reconfig/geometry/primitives.h"

namespace reconfig::sculpt {
namespace {

/// Distance to a dense sampling of the shape's boundary: the oracle (an upper bound, tight to the spacing).
double sampled_distance(const std::vector<Eigen::Vector3d>& boundary, const Eigen::Vector3d& p) {
  double best = 1e300;
  for (const Eigen::Vector3d& q : boundary) best = std::min(best, (q - p).norm());
  return best;
}

std::vector<Eigen::Vector3d> sample_surface(const std::function<Eigen::Vector3d(double, double)>& surface, int n) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j < 2 * n; ++j) points.push_back(surface(M_PI * i / n, M_PI * j / n));
  return points;
}

TEST(Tool, PrimitiveDistancesMatchDenseSamplingOfTheirSurfaces) {
  const Eigen::Vector3d center(0.3, -0.2, 0.5);
  const Tool sphere = Tool::sphere(0.4, center, 0.2);
  const Tool capsule = Tool::capsule(0.2, 0.6, center, 0.2);
  auto on_sphere = [&](double a, double b) {
    return Eigen::Vector3d(center + 0.4 * Eigen::Vector3d(std::sin(a) * std::cos(b), std::sin(a) * std::sin(b), std::cos(a)));
  };
  std::vector<Eigen::Vector3d> sphere_points = sample_surface(on_sphere, 400);
  std::vector<Eigen::Vector3d> capsule_points;  // a cylinder and two half spheres
  for (int i = 0; i <= 200; ++i)
    for (int j = 0; j < 400; ++j) {
      const double b = M_PI * j / 200, a = M_PI * i / 200;
      const Eigen::Vector3d dir(std::sin(a) * std::cos(b), std::sin(a) * std::sin(b), std::cos(a));
      capsule_points.push_back(center + 0.2 * dir + Eigen::Vector3d(0, 0, dir.z() > 0 ? 0.3 : -0.3));
      capsule_points.push_back(center + Eigen::Vector3d(0.2 * std::cos(b), 0.2 * std::sin(b), -0.3 + 0.6 * i / 200));
    }
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector3d p = center + Eigen::Vector3d(unit(random), unit(random), unit(random));
    EXPECT_NEAR(std::abs(sphere.distance(p)), sampled_distance(sphere_points, p), 5e-3);
    EXPECT_NEAR(std::abs(capsule.distance(p)), sampled_distance(capsule_points, p), 5e-3);
  }
}

TEST(Tool, BoxDistanceMatchesTheBakedMeshOfTheSameBox) {
  const Eigen::Vector3d size(0.4, 0.6, 0.2);
  const Tool box = Tool::box(size, Eigen::Vector3d::Zero(), 0.5);
  const Tool baked = Tool::baked(geometry::make_box(size), 0.5);
  std::mt19937 random(4);
  std::uniform_real_distribution<double> unit(-0.6, 0.6);
  for (int i = 0; i < 300; ++i) {
    const Eigen::Vector3d p(unit(random), unit(random), unit(random));
    if (baked.distance(p) >= 0.5) continue;  // a baked tool stops searching beyond its coating
    EXPECT_NEAR(box.distance(p), baked.distance(p), 1e-12) << p.transpose();
  }
}

TEST(Tool, FieldGradientsMatchFiniteDifferencesAndDistancesAreOneLipschitz) {
  const Eigen::Vector3d c(0.1, 0.2, 0.3);
  Tool rotated_box = Tool::box({0.3, 0.2, 0.5}, c, 0.3);
  ToolPose pose = rotated_box.pose();
  pose.rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized());
  pose.scale = 1.3;
  rotated_box.set_pose(pose);
  const std::vector<Tool> tools = {Tool::sphere(0.3, c, 0.25), rotated_box, Tool::capsule(0.1, 0.4, c, 0.3),
                                   Tool::ellipsoid({0.4, 0.2, 0.1}, c, 0.3),
                                   Tool::baked(geometry::make_sphere(0.3, 3), 0.3)};
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-0.9, 0.9);
  const double e = 1e-6;
  for (const Tool& tool : tools) {
    int in_coating = 0;
    for (int i = 0; i < 300; ++i) {
      const Eigen::Vector3d p = c + Eigen::Vector3d(unit(random), unit(random), unit(random));
      Eigen::Vector3d gradient;
      const double phi = tool.field(p, gradient);
      if (phi <= 0 || phi >= 1) continue;
      ++in_coating;
      for (int axis = 0; axis < 3; ++axis) {
        const Eigen::Vector3d step = e * Eigen::Vector3d::Unit(axis);
        EXPECT_NEAR(gradient[axis], (tool.field(p + step) - tool.field(p - step)) / (2 * e), 1e-5);
      }
      Eigen::Vector3d distance_gradient;
      tool.distance(p, distance_gradient);
      EXPECT_LE(distance_gradient.norm(), 1 + 1e-12);
      EXPECT_TRUE(tool.field_box().contains(p)) << static_cast<int>(tool.shape()) << " " << p.transpose();
    }
    EXPECT_GT(in_coating, 20) << static_cast<int>(tool.shape());
  }
}

}  // namespace
}  // namespace reconfig::sculpt
