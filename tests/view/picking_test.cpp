#include "reconfig/view/picking.h"

#include <gtest/gtest.h>

#include "reconfig/geometry/primitives.h"

namespace reconfig::view {
namespace {

TEST(Picking, CenterPixelRayLooksAtTarget) {
  Camera camera;
  camera.target = {0.2, 0.1, 0.3};
  camera.distance = 3;
  const Ray ray = ray_from_pixel(camera, 640, 480, 320, 240);
  EXPECT_TRUE(ray.origin.isApprox(camera.eye()));
  EXPECT_TRUE(ray.direction.isApprox(camera.forward(), 1e-12));
}

TEST(Picking, ProjectInvertsRayFromPixel) {
  Camera camera;
  camera.yaw = 0.3;
  camera.pitch = 0.6;
  for (const Eigen::Vector2d& pixel : {Eigen::Vector2d(10.5, 20.5), Eigen::Vector2d(600, 5), Eigen::Vector2d(320, 470)}) {
    const Ray ray = ray_from_pixel(camera, 640, 480, pixel.x(), pixel.y());
    const auto projected = project_to_pixel(camera, 640, 480, ray.at(2.5));
    ASSERT_TRUE(projected);
    EXPECT_NEAR(projected->pixel.x(), pixel.x(), 1e-9);
    EXPECT_NEAR(projected->pixel.y(), pixel.y(), 1e-9);
  }
  EXPECT_FALSE(project_to_pixel(camera, 640, 480, camera.eye() - camera.forward()));
  // A point above the target appears above the center (smaller y).
  const auto above = project_to_pixel(camera, 640, 480, camera.target + Eigen::Vector3d(0, 0, 0.1));
  ASSERT_TRUE(above);
  EXPECT_LT(above->pixel.y(), 240);
}

TEST(Picking, RayTriangleHitsInsideAndMissesOutside) {
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  const Ray down{{0.2, 0.2, 2}, {0, 0, -1}};
  const auto hit = ray_triangle(down, a, b, c);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(*hit, 2.0, 1e-12);
  EXPECT_TRUE(ray_triangle(down, a, c, b));  // both orientations
  EXPECT_FALSE(ray_triangle({{0.8, 0.8, 2}, {0, 0, -1}}, a, b, c));  // outside the hypotenuse
  EXPECT_FALSE(ray_triangle({{0.2, 0.2, 2}, {0, 0, 1}}, a, b, c));   // triangle behind
  EXPECT_FALSE(ray_triangle({{0.2, 0.2, 2}, {1, 0, 0}}, a, b, c));   // parallel
}

TEST(Picking, RayPlaneMeetsThePlaneInFrontOnly) {
  const Ray ray{{0.5, -1, 3}, Eigen::Vector3d(0.2, 0.1, -1).normalized()};
  const Eigen::Vector3d point(4, 7, 1), normal(0, 0, 2);  // the plane z = 1
  const auto s = ray_plane(ray, point, normal);
  ASSERT_TRUE(s);
  EXPECT_NEAR(ray.at(*s).z(), 1.0, 1e-12);
  EXPECT_FALSE(ray_plane(ray, Eigen::Vector3d(0, 0, 5), normal));                // behind
  EXPECT_FALSE(ray_plane({{0, 0, 3}, {1, 0, 0}}, point, normal));                // parallel
  EXPECT_NEAR(*ray_plane(ray, point, -normal), *s, 1e-12);                       // either side's normal
}

TEST(Picking, RayMeshReturnsNearestFace) {
  const geometry::Mesh box = geometry::make_box(Eigen::Vector3d(2, 2, 2));
  const Ray ray{{0.1, 0.2, 5}, {0, 0, -1}};
  const auto hit = ray_mesh(ray, box.V, box.F);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->s, 4.0, 1e-12);  // the top face z = 1, not the bottom z = -1
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(box.V(box.F(hit->face, k), 2), 1.0, 1e-12);
  EXPECT_FALSE(ray_mesh({{3, 3, 5}, {0, 0, -1}}, box.V, box.F));
}

}  // namespace
}  // namespace reconfig::view
