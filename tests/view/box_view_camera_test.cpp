#include "reconfig/view/box_view_camera.h"

#include <gtest/gtest.h>

#include <cmath>

#include "reconfig/view/picking.h"
#include "reconfig/view/view_candidates.h"

namespace reconfig::view {
namespace {

// Every corner of the box projects inside the viewport from every direction; and the distance
// is the smallest that can promise it: the bounding sphere touches the view cone.
TEST(BoxViewCamera, KeepsTheWholeBoxInViewFromAnyDirection) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d(-0.2, 0.1, 0.3), Eigen::Vector3d(0.5, 0.3, 0.9));
  for (double aspect : {1.0, 16.0 / 9, 0.5})
    for (const Eigen::Vector3d& d : random_view_directions(300, false, 11)) {
      const Camera camera = box_view_camera(box, d, aspect);
      const int width = static_cast<int>(200 * aspect), height = 200;
      EXPECT_NEAR((camera.target - box.center()).norm(), 0, 1e-12);
      for (int c = 0; c < 8; ++c) {
        const auto p = project_to_pixel(camera, width, height, box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)));
        ASSERT_TRUE(p);
        EXPECT_GE(p->pixel.x(), 0);
        EXPECT_LE(p->pixel.x(), width);
        EXPECT_GE(p->pixel.y(), 0);
        EXPECT_LE(p->pixel.y(), height);
        EXPECT_GT(p->depth, camera.near_plane);
        EXPECT_LT(p->depth, camera.far_plane);
      }
      const double half = std::min(camera.fov_y, camera.fov_x(aspect)) / 2;
      EXPECT_NEAR(std::asin(0.5 * box.diagonal().norm() / camera.distance), half, 1e-9);
    }
}

TEST(BoxViewCamera, LooksAlongTheDirectionWithUpZ) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1));
  for (const Eigen::Vector3d& d : random_view_directions(100, false, 5)) {
    const Camera camera = box_view_camera(box, 3 * d);
    if (std::abs(d.z()) > std::sin(Camera::kMaxPitch)) continue;  // pitch clamped
    EXPECT_NEAR((-camera.forward() - d).norm(), 0, 1e-9);
    EXPECT_GE(camera.up().z(), 0);
  }
  const Camera down = box_view_camera(box, Eigen::Vector3d::UnitZ());
  EXPECT_LT(std::acos(-down.forward().z()), 1.5 * M_PI / 180);  // clamped: 1.2° off
}

TEST(BoxViewCamera, GivesAPointBoxTheMinimumRadius) {
  const Eigen::AlignedBox3d point(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(1, 2, 3));
  const Camera camera = box_view_camera(point, Eigen::Vector3d::UnitX(), 1, 0.7, 0.5);
  EXPECT_NEAR(camera.distance, 0.5 / std::sin(0.35), 1e-12);
  EXPECT_NEAR((camera.eye() - Eigen::Vector3d(1 + camera.distance, 2, 3)).norm(), 0, 1e-9);
}

}  // namespace
}  // namespace reconfig::view
