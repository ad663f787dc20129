// The first view of a design: from its working side, or as it was saved.

#include <gtest/gtest.h>

#include "reconfig/scene/scene_file.h"
#include "studio_test_util.h"

namespace reconfig::studio {
namespace {

std::filesystem::path kitchen_copy() {
  const std::filesystem::path dir = testing::fresh_temp_dir() / "kitchen";
  std::filesystem::copy(testing::source_dir() / "examples" / "kitchen", dir, std::filesystem::copy_options::recursive);
  return dir / "scene.json";
}

// The complaint: the kitchen opened from behind its wall (y < 0). It opens from the
// room, where its drawers come out; saved, it reopens with the camera it was left with.
TEST(FirstView, KitchenOpensFromTheRoomAndReopensAsSaved) {
  const std::filesystem::path file = kitchen_copy();
  HeadlessFrontend frontend(1000, 700, StudioOptions{});
  Studio& studio = frontend.studio();
  ASSERT_TRUE(studio.open(file)) << studio.status();
  frontend.run_frame();
  const view::Camera first = studio.camera();
  EXPECT_GT(first.eye().y() - first.target.y(), 0.5 * first.distance);
  EXPECT_GT(first.eye().z(), first.target.z());

  // Looking around is no edit; saving keeps the camera.
  studio.camera().orbit(0.4, 0.2);
  studio.camera().zoom(0.8);
  EXPECT_FALSE(studio.document()->modified());
  const view::Camera saved = studio.camera();
  ASSERT_TRUE(studio.save()) << studio.status();
  const scene::Reconfigurable on_disk = scene::load_scene(file);
  ASSERT_TRUE(on_disk.view);
  EXPECT_NEAR(on_disk.view->distance, saved.distance, 1e-12);

  studio.camera().orbit(2, 0);
  ASSERT_TRUE(studio.open(file)) << studio.status();
  frontend.run_frame();
  const view::Camera reopened = studio.camera();
  EXPECT_TRUE(reopened.target.isApprox(saved.target, 1e-12));
  EXPECT_NEAR(reopened.distance, saved.distance, 1e-12);
  EXPECT_NEAR(reopened.yaw, saved.yaw, 1e-12);
  EXPECT_NEAR(reopened.pitch, saved.pitch, 1e-12);
  EXPECT_FALSE(studio.document()->modified());
}

}  // namespace
}  // namespace reconfig::studio
