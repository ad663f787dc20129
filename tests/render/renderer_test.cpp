#include "reconfig/render/renderer.h"

#include <gtest/gtest.h>

#include "reconfig/geometry/primitives.h"
#include "reconfig/view/picking.h"
#include "render_fixture.h"

namespace reconfig::render {
namespace {

using testing::color_distance;
using testing::RenderTest;

constexpr int kWidth = 160, kHeight = 120;

view::Camera camera_looking_at_origin() {
  view::Camera camera;
  camera.target = Eigen::Vector3d::Zero();
  camera.distance = 4;
  camera.yaw = -1.2;
  camera.pitch = 0.35;
  camera.near_plane = 0.1;
  camera.far_plane = 50;
  return camera;
}

MeshItem red_box() {
  const geometry::Mesh box = geometry::make_box(Eigen::Vector3d(1, 1, 1));
  MeshItem item;
  item.V = box.V;
  item.F = box.F;
  item.color = {0.9f, 0.1f, 0.1f};
  return item;
}

DrawList plain_list() {
  DrawList list;
  list.grid.visible = false;
  list.background = {1.0f, 1.0f, 1.0f};
  return list;
}

TEST_F(RenderTest, ContextIsOpenGl33Core) {
  EXPECT_FALSE(context_->renderer().empty());
  const std::string version = context_->version();
  ASSERT_GE(version.size(), 3u);
  EXPECT_GE((version[0] - '0') * 10 + (version[2] - '0'), 33) << version;
}

TEST_F(RenderTest, RedBoxCoversTheCenterNotTheCorner) {
  DrawList list = plain_list();
  list.meshes.push_back(red_box());
  const Image image = renderer().render(list, camera_looking_at_origin(), kWidth, kHeight);
  ASSERT_EQ(image.width, kWidth);
  ASSERT_EQ(image.height, kHeight);
  ASSERT_EQ(image.rgba.size(), static_cast<std::size_t>(kWidth * kHeight * 4));
  const auto center = image.pixel(kWidth / 2, kHeight / 2);
  EXPECT_GT(center[0], 100);
  EXPECT_LT(center[1], 60);
  EXPECT_LT(center[2], 60);
  EXPECT_EQ(center[3], 255);
  const auto corner = image.pixel(2, 2);
  EXPECT_EQ(corner[0], 255);
  EXPECT_EQ(corner[1], 255);
  EXPECT_EQ(corner[2], 255);
  EXPECT_EQ(corner[3], 255);
}

TEST_F(RenderTest, PixelsFollowTheCameraProjection) {
  // A small box placed off-center lands where view::project_to_pixel says (top rows stay top).
  const view::Camera camera = camera_looking_at_origin();
  DrawList list = plain_list();
  MeshItem box = red_box();
  const Eigen::Vector3d offset = 0.9 * camera.up() + 1.2 * camera.right();
  box.V *= 0.2;
  box.V.rowwise() += offset.transpose();
  list.meshes.push_back(box);
  const Image image = renderer().render(list, camera, kWidth, kHeight);
  const auto projected = view::project_to_pixel(camera, kWidth, kHeight, offset);
  ASSERT_TRUE(projected);
  const int x = static_cast<int>(projected->pixel.x()), y = static_cast<int>(projected->pixel.y());
  ASSERT_GT(x, kWidth / 2);
  ASSERT_LT(y, kHeight / 2);
  EXPECT_GT(image.pixel(x, y)[0], 100);
  EXPECT_LT(image.pixel(x, y)[1], 60);
  EXPECT_EQ(image.pixel(kWidth - 1 - x, kHeight - 1 - y)[1], 255);  // the mirrored spot is empty
}

TEST_F(RenderTest, TransparentBoxTintsWhatIsBehindIt) {
  const view::Camera camera = camera_looking_at_origin();
  DrawList list = plain_list();
  list.meshes.push_back(red_box());
  const Image before = renderer().render(list, camera, kWidth, kHeight);
  BoxItem box;
  // Between the eye and the red box, in front of its middle.
  const Eigen::Vector3d in_front = camera.target - 1.0 * camera.forward();
  box.box = Eigen::AlignedBox3d(in_front.array() - 0.15, in_front.array() + 0.15);
  box.color = {0.1f, 0.2f, 1.0f};
  box.pulsate = false;
  list.boxes.push_back(box);
  const Image after = renderer().render(list, camera, kWidth, kHeight);
  const auto at = view::project_to_pixel(camera, kWidth, kHeight, box.box.center());
  ASSERT_TRUE(at);
  const auto x = static_cast<int>(at->pixel.x()), y = static_cast<int>(at->pixel.y());
  const auto b = before.pixel(x, y), a = after.pixel(x, y);
  EXPECT_GT(a[2], b[2] + 20) << "the box should add blue";
  EXPECT_LT(a[2], 250) << "but stay transparent, not opaque blue";
  EXPECT_EQ(color_distance(before.pixel(2, 2), after.pixel(2, 2)), 0) << "far from the box nothing changes";
  EXPECT_EQ(color_distance(before.pixel(kWidth / 2, kHeight - 3), after.pixel(kWidth / 2, kHeight - 3)), 0);

  // A pulsating box changes its opacity with the clock.
  list.boxes[0].pulsate = true;
  list.seconds = 0.25;
  const Image strong = renderer().render(list, camera, kWidth, kHeight);
  list.seconds = 0.75;
  const Image weak = renderer().render(list, camera, kWidth, kHeight);
  EXPECT_GT(strong.pixel(x, y)[2], weak.pixel(x, y)[2]);
}

TEST_F(RenderTest, HighlightedMeshLooksDifferentOnlyWhereItIs) {
  const view::Camera camera = camera_looking_at_origin();
  DrawList list = plain_list();
  MeshItem left = red_box(), right = red_box();
  left.V.col(0).array() -= 1.0;
  right.V.col(0).array() += 1.0;
  left.color = right.color = {0.5f, 0.5f, 0.5f};
  list.meshes = {left, right};
  const Image plain = renderer().render(list, camera, kWidth, kHeight);
  list.meshes[1].highlighted = true;
  const Image selected = renderer().render(list, camera, kWidth, kHeight);
  if (std::getenv("RECONFIG_RENDER_DUMP")) {
    write_png("/tmp/render/plain.png", plain);
    write_png("/tmp/render/selected.png", selected);
  }
  int changed = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      if (color_distance(plain.pixel(x, y), selected.pixel(x, y)) < 30) continue;
      ++changed;
      const view::Ray ray = view::ray_from_pixel(camera, kWidth, kHeight, x + 0.5, y + 0.5);
      const auto hit_right = view::ray_mesh(ray, right.V, right.F);
      const auto hit_left = view::ray_mesh(ray, left.V, left.F);
      // Changed pixels show the selected part (or touch it: antialiased silhouette pixels).
      const bool near_right = testing::hits_near(camera, kWidth, kHeight, x, y, right.V, right.F);
      EXPECT_TRUE(near_right) << "pixel " << x << "," << y;
      if (hit_left && hit_right) {
        EXPECT_LT(hit_right->s, hit_left->s);
      }
    }
  EXPECT_GT(changed, 100);
  // The highlight warms the part: more red than blue.
  const auto at = view::project_to_pixel(camera, kWidth, kHeight, Eigen::Vector3d(1, 0, 0.5));
  ASSERT_TRUE(at);
  const auto p = selected.pixel(static_cast<int>(at->pixel.x()), static_cast<int>(at->pixel.y()));
  EXPECT_GT(p[0], p[2] + 40);
}

TEST_F(RenderTest, LinesArrowsAndGridDraw) {
  const view::Camera camera = camera_looking_at_origin();
  DrawList list = plain_list();
  const Image empty = renderer().render(list, camera, kWidth, kHeight);
  list.grid.visible = true;
  list.grid.height = -0.5;
  list.grid.spacing = 0.25;
  list.grid.half_lines = 8;
  list.lines.push_back({{{-1, 0, 1}, {0, 0, 1.3}, {1, 0, 1}}, {0, 0, 0, 1}, true});
  list.arrows.push_back({{0, 0, 0}, {0, 0, 1}, {0.1f, 0.3f, 0.9f}, 0.3});
  const Image drawn = renderer().render(list, camera, kWidth, kHeight);
  int changed = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) changed += color_distance(empty.pixel(x, y), drawn.pixel(x, y)) > 30;
  EXPECT_GT(changed, 300);
  const auto head = view::project_to_pixel(camera, kWidth, kHeight, Eigen::Vector3d(0, 0, 0.85));
  ASSERT_TRUE(head);
  const auto p = drawn.pixel(static_cast<int>(head->pixel.x()), static_cast<int>(head->pixel.y()));
  EXPECT_GT(p[2], p[0] + 40) << "the blue arrow head";
}

}  // namespace
}  // namespace reconfig::render
