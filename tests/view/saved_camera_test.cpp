#include "reconfig/view/saved_camera.h"

#include <gtest/gtest.h>

namespace reconfig::view {
namespace {

TEST(SavedCamera, ACameraComesBackAsItWasSaved) {
  Camera camera;
  camera.target = Eigen::Vector3d(0.3, -2, 1);
  camera.distance = 4.5;
  camera.yaw = 1.2;
  camera.pitch = -0.3;
  const scene::SavedView saved = saved_view(camera);
  EXPECT_NEAR(saved.yaw_degrees, 1.2 * 180 / M_PI, 1e-12);
  EXPECT_NEAR(saved.pitch_degrees, -0.3 * 180 / M_PI, 1e-12);
  const Eigen::AlignedBox3d box(Eigen::Vector3d(-1, -3, 0), Eigen::Vector3d(1, -1, 2));
  const Camera back = camera_from(saved, box);
  EXPECT_EQ(back.target, camera.target);
  EXPECT_EQ(back.distance, 4.5);
  EXPECT_NEAR(back.yaw, 1.2, 1e-12);
  EXPECT_NEAR(back.pitch, -0.3, 1e-12);
  // The planes enclose the box seen from the saved eye.
  for (int c = 0; c < 8; ++c) {
    const double depth = (box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)) - back.eye()).dot(back.forward());
    EXPECT_GT(depth, back.near_plane);
    EXPECT_LT(depth, back.far_plane);
  }
}

TEST(SavedCamera, PitchIsKeptShortOfStraightDown) {
  const Camera camera = camera_from({.target = Eigen::Vector3d::Zero(), .distance = 2, .yaw_degrees = 0, .pitch_degrees = 89.9},
                                    Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-1), Eigen::Vector3d::Constant(1)));
  EXPECT_EQ(camera.pitch, Camera::kMaxPitch);
}

}  // namespace
}  // namespace reconfig::view
