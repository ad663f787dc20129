#include "reconfig/view/camera.h"

#include <gtest/gtest.h>

#include <cmath>

#include "reconfig/view/picking.h"

namespace reconfig::view {
namespace {

Eigen::Vector3d to_clip_ndc(const Camera& camera, double aspect, const Eigen::Vector3d& p) {
  const Eigen::Vector4d clip = camera.projection_matrix(aspect) * camera.view_matrix() * p.homogeneous();
  return clip.head<3>() / clip.w();
}

TEST(Camera, EyeFollowsYawAndPitch) {
  Camera camera;
  camera.target = {1, 2, 3};
  camera.distance = 2;
  camera.yaw = 0;
  camera.pitch = 0;
  EXPECT_TRUE(camera.eye().isApprox(Eigen::Vector3d(3, 2, 3)));
  camera.yaw = M_PI / 2;
  EXPECT_TRUE(camera.eye().isApprox(Eigen::Vector3d(1, 4, 3)));
  camera.pitch = 1.0;
  EXPECT_NEAR(camera.eye().z(), 3 + 2 * std::sin(1.0), 1e-12);
}

TEST(Camera, ViewMatrixIsRigidAndMapsTargetOntoMinusZ) {
  Camera camera;
  camera.target = {0.3, -0.2, 0.5};
  camera.distance = 4;
  camera.yaw = 0.7;
  camera.pitch = 0.3;
  const Eigen::Matrix4d view = camera.view_matrix();
  const Eigen::Matrix3d R = view.topLeftCorner<3, 3>();
  EXPECT_TRUE((R * R.transpose()).isApprox(Eigen::Matrix3d::Identity(), 1e-12));
  EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
  const Eigen::Vector4d target = view * camera.target.homogeneous();
  EXPECT_TRUE(target.head<3>().isApprox(Eigen::Vector3d(0, 0, -4), 1e-12));
  // World up (+z) points up on screen: positive eye-space y.
  const Eigen::Vector4d above = view * (camera.target + Eigen::Vector3d::UnitZ()).homogeneous();
  EXPECT_GT(above.y(), 0.0);
  // Screen right is right of the view direction.
  EXPECT_NEAR(camera.right().dot(camera.forward()), 0.0, 1e-12);
  EXPECT_NEAR(camera.right().z(), 0.0, 1e-12);
}

TEST(Camera, ProjectionMapsNearAndFarToDepthBounds) {
  Camera camera;
  camera.target = Eigen::Vector3d::Zero();
  camera.distance = 5;
  camera.near_plane = 1;
  camera.far_plane = 9;
  const Eigen::Vector3d f = camera.forward();
  EXPECT_NEAR(to_clip_ndc(camera, 1.5, camera.eye() + f * 1).z(), -1.0, 1e-9);
  EXPECT_NEAR(to_clip_ndc(camera, 1.5, camera.eye() + f * 9).z(), 1.0, 1e-9);
  EXPECT_NEAR(to_clip_ndc(camera, 1.5, camera.target).x(), 0.0, 1e-12);
}

TEST(Camera, FrameAllKeepsEveryCornerOnScreen) {
  for (double aspect : {0.5, 1.0, 16.0 / 9}) {
    Camera camera;
    camera.yaw = -0.9;
    camera.pitch = 0.4;
    const Eigen::AlignedBox3d box(Eigen::Vector3d(-1, -0.2, 0), Eigen::Vector3d(1.5, 0.4, 0.9));
    camera.frame_all(box, aspect);
    EXPECT_TRUE(camera.target.isApprox(box.center()));
    double largest = 0;
    for (int c = 0; c < 8; ++c) {
      const Eigen::Vector3d ndc = to_clip_ndc(camera, aspect, box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)));
      EXPECT_LT(std::abs(ndc.x()), 1.0) << "aspect " << aspect;
      EXPECT_LT(std::abs(ndc.y()), 1.0) << "aspect " << aspect;
      EXPECT_GT(ndc.z(), -1.0);
      EXPECT_LT(ndc.z(), 1.0);
      largest = std::max({largest, std::abs(ndc.x()), std::abs(ndc.y())});
    }
    // The tightest fit: the outermost corner touches the frame shrunk by the margin 1.1.
    EXPECT_NEAR(largest, 1 / 1.1, 1e-9) << "aspect " << aspect;
  }
}

TEST(Camera, OrbitClampsPitchAndZoomScalesPlanes) {
  Camera camera;
  camera.orbit(0.1, 10);
  EXPECT_DOUBLE_EQ(camera.pitch, Camera::kMaxPitch);
  const double near = camera.near_plane, distance = camera.distance;
  camera.zoom(2);
  EXPECT_DOUBLE_EQ(camera.distance, 2 * distance);
  EXPECT_DOUBLE_EQ(camera.near_plane, 2 * near);
  const Eigen::Vector3d before = camera.target;
  camera.pan(1, 0);
  EXPECT_TRUE((camera.target - before).isApprox(camera.right()));
}

}  // namespace
}  // namespace reconfig::view
