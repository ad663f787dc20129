#include "gizmo.h"

#include <gtest/gtest.h>

#include <random>

#include "random_camera.h"

namespace reconfig::studio {
namespace {

constexpr int kWidth = 800, kHeight = 600;

view::Ray ray_through(const view::Camera& camera, const Eigen::Vector3d& point) {
  const auto pixel = view::project_to_pixel(camera, kWidth, kHeight, point);
  EXPECT_TRUE(pixel.has_value());
  return view::ray_from_pixel(camera, kWidth, kHeight, pixel->pixel.x(), pixel->pixel.y());
}

// Oracle: dragging the mouse from one point of an axis to another point of it moves the part
// by exactly the distance between them along that axis, from any viewpoint.
TEST(Gizmo, ArrowDragsTranslateByTheDistanceAlongTheAxis) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (int trial = 0; trial < 200; ++trial) {
    const view::Camera camera = random_camera(random);
    const Eigen::Vector3d center = camera.target + Eigen::Vector3d(u(random), u(random), u(random));
    for (const GizmoHandle handle : {GizmoHandle::kMoveX, GizmoHandle::kMoveY, GizmoHandle::kMoveZ}) {
      const Eigen::Vector3d axis = handle_axis(handle);
      // Skip axes seen nearly end-on: there the drag is ill-conditioned by design.
      if (std::abs(axis.dot(camera.forward())) > 0.9) continue;
      const double a = u(random), b = u(random);
      GizmoDrag drag{handle, center, motion::Pose{}, ray_through(camera, center + a * axis)};
      drag.start_pose.translation = Eigen::Vector3d(1, 2, 3);
      const motion::Pose pose = drag.pose_for(ray_through(camera, center + b * axis));
      EXPECT_NEAR((pose.translation - Eigen::Vector3d(1, 2, 3) - (b - a) * axis).norm(), 0, 1e-7)
          << "trial " << trial;
      EXPECT_TRUE(pose.rotation.isApprox(drag.start_pose.rotation));
    }
  }
}

// Oracle: dragging along a ring from angle α to angle β rotates by β − α about its axis and
// keeps the pivot where it is.
TEST(Gizmo, RingDragsRotateByTheAngleTurned) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> angle(-3, 3);
  for (int trial = 0; trial < 200; ++trial) {
    const view::Camera camera = random_camera(random);
    const Eigen::Vector3d center = camera.target;
    for (const GizmoHandle handle : {GizmoHandle::kRotateX, GizmoHandle::kRotateY, GizmoHandle::kRotateZ}) {
      const Eigen::Vector3d axis = handle_axis(handle);
      if (std::abs(axis.dot(camera.forward())) < 0.2) continue;  // ring seen edge-on
      const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u);
      const double a = angle(random), b = angle(random);
      const auto on_ring = [&](double t) { return center + 0.4 * (std::cos(t) * u + std::sin(t) * v); };
      motion::Pose start;
      start.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 1, 0).normalized()));
      start.translation = Eigen::Vector3d(0.5, 0, 0);
      const GizmoDrag drag{handle, center, start, ray_through(camera, on_ring(a))};
      const motion::Pose pose = drag.pose_for(ray_through(camera, on_ring(b)));
      const Eigen::Quaterniond expected(Eigen::AngleAxisd(b - a, axis) * start.rotation);
      EXPECT_GT(std::abs(pose.rotation.dot(expected)), 1 - 1e-9) << "trial " << trial;
      EXPECT_EQ(pose.translation, start.translation);
    }
  }
}

TEST(Gizmo, HitFindsTheHandleUnderTheMouseAndNothingElsewhere) {
  view::Camera camera;
  camera.target = Eigen::Vector3d::Zero();
  const Gizmo gizmo = Gizmo::sized_for(camera, kHeight, Eigen::Vector3d::Zero());
  for (const GizmoHandle handle : {GizmoHandle::kMoveX, GizmoHandle::kMoveY, GizmoHandle::kMoveZ}) {
    const auto tip = view::project_to_pixel(camera, kWidth, kHeight, gizmo.center + gizmo.arrow_length * handle_axis(handle));
    ASSERT_TRUE(tip);
    EXPECT_EQ(gizmo.hit(camera, kWidth, kHeight, tip->pixel), handle);
    // The arrows keep their size on screen: 90 pixels from the center to the tip, or less
    // when the axis leans towards the viewer.
    const auto base = view::project_to_pixel(camera, kWidth, kHeight, gizmo.center);
    EXPECT_LE((tip->pixel - base->pixel).norm(), 90.5);
  }
  const auto ring_point = view::project_to_pixel(camera, kWidth, kHeight, gizmo.shape(GizmoHandle::kRotateZ)[5]);
  EXPECT_EQ(gizmo.hit(camera, kWidth, kHeight, ring_point->pixel), GizmoHandle::kRotateZ);
  EXPECT_EQ(gizmo.hit(camera, kWidth, kHeight, {5, 5}), GizmoHandle::kNone);
}

TEST(Gizmo, RaysParallelToTheAxisKeepTheStartPose) {
  GizmoDrag drag{GizmoHandle::kMoveZ, Eigen::Vector3d::Zero(), motion::Pose{},
                 view::Ray{Eigen::Vector3d(0, 0, 5), Eigen::Vector3d(0, 0, -1)}};
  const motion::Pose pose = drag.pose_for(view::Ray{Eigen::Vector3d(0.1, 0, 5), Eigen::Vector3d(0, 0, -1)});
  EXPECT_EQ(pose.translation, Eigen::Vector3d::Zero());
}

}  // namespace
}  // namespace reconfig::studio
