#include "handle_drag.h"

#include <gtest/gtest.h>

#include <random>

#include "random_camera.h"

namespace reconfig::studio {
namespace {

constexpr int kWidth = 800, kHeight = 600;

std::vector<motion::TranslationKey> random_keys(std::mt19937& random, int n) {
  std::uniform_real_distribution<double> u(-0.4, 0.4);
  const auto point = [&] { return Eigen::Vector3d(u(random), u(random), u(random)); };
  std::vector<motion::TranslationKey> keys;
  for (int k = 0; k < n; ++k) keys.push_back({k / (n - 1.0), point(), point(), point()});
  return keys;
}

TEST(HandleDrag, OnlyTheHandlesThatShapeTheMotionCount) {
  std::mt19937 random(1);
  const auto keys = random_keys(random, 3);
  const std::vector<HandleRef> expected{{0, true}, {1, false}, {1, true}, {2, false}};
  EXPECT_EQ(shaping_handles(keys), expected);
}

// Oracle: clicking where a handle's end is drawn finds that handle; dragging it to another
// pixel puts its end under that pixel at the depth it had (in the plane facing the camera),
// and changes nothing else of the key — from any viewpoint.
TEST(HandleDrag, TheHandleEndFollowsTheMouseInThePlaneFacingTheCamera) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> pixels(-60, 60);
  int checked = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const view::Camera camera = random_camera(random);
    const auto keys = random_keys(random, 4);
    const Eigen::Vector3d pivot = camera.target;
    const std::vector<HandleRef> handles = shaping_handles(keys);
    const HandleRef handle = handles[random() % handles.size()];
    const Eigen::Vector3d end = handle_end(keys[handle.key], pivot, handle.out);
    const auto at = view::project_to_pixel(camera, kWidth, kHeight, end);
    ASSERT_TRUE(at.has_value());
    // Another handle's end may be drawn at (nearly) the same pixel: then either is a fair hit.
    const auto hit = hit_handle(keys, pivot, camera, kWidth, kHeight, at->pixel);
    ASSERT_TRUE(hit.has_value());
    const auto hit_at = view::project_to_pixel(camera, kWidth, kHeight, handle_end(keys[hit->key], pivot, hit->out));
    EXPECT_LE((hit_at->pixel - at->pixel).norm(), 1e-6 + (hit == handle ? 0 : 7));
    EXPECT_FALSE(hit_handle(keys, pivot, camera, kWidth, kHeight, Eigen::Vector2d(-100, -100)).has_value());

    const Eigen::Vector2d target = at->pixel + Eigen::Vector2d(pixels(random), pixels(random));
    const HandleDrag drag{handle, keys[handle.key], end, camera.forward(),
                          view::ray_from_pixel(camera, kWidth, kHeight, at->pixel.x(), at->pixel.y())};
    const motion::TranslationKey moved = drag.key_for(view::ray_from_pixel(camera, kWidth, kHeight, target.x(), target.y()));
    const Eigen::Vector3d new_end = pivot + (handle.out ? moved.out : moved.in);
    const auto now = view::project_to_pixel(camera, kWidth, kHeight, new_end);
    ASSERT_TRUE(now.has_value());
    EXPECT_LE((now->pixel - target).norm(), 1e-6);
    EXPECT_NEAR((new_end - end).dot(camera.forward()), 0, 1e-9);
    const motion::TranslationKey& before = keys[handle.key];
    EXPECT_EQ(moved.time, before.time);
    EXPECT_EQ(moved.point, before.point);
    EXPECT_EQ(handle.out ? moved.in : moved.out, handle.out ? before.in : before.out);
    ++checked;
  }
  EXPECT_EQ(checked, 300);
}

}  // namespace
}  // namespace reconfig::studio
