#include "reconfig/view/working_side.h"

#include <gtest/gtest.h>

#include <cmath>

#include "reconfig/geometry/primitives.h"
#include "reconfig/scene/scene_file.h"
#include "reconfig/view/scene_bounds.h"
#include "support/test_data.h"

namespace reconfig::view {
namespace {

Camera first_view(const scene::Reconfigurable& scene) {
  Camera camera;
  aim_at_working_side(camera, scene);
  camera.frame_all(scene_bounds_over(scene, 0), 1.5);
  return camera;
}

// The kitchen stands against a wall at y < 0 and its drawers, doors and pull-outs come out
// along +y: the first view looks from the room (+y), not from behind the wall.
TEST(WorkingSide, KitchenIsSeenFromTheRoom) {
  const scene::Reconfigurable kitchen = scene::load_scene(testing::source_dir() / "examples/kitchen/scene.json");
  const Eigen::Vector2d direction = working_direction(kitchen);
  EXPECT_GT(direction.y(), 10 * std::abs(direction.x()));
  const Camera camera = first_view(kitchen);
  const Eigen::Vector3d eye = camera.eye();
  EXPECT_GT(eye.y() - camera.target.y(), 0.8 * camera.distance * std::cos(camera.pitch));
  EXPECT_GT(eye.z(), camera.target.z());
  // The whole first transition is in view, so its collisions are too.
  const Eigen::AlignedBox3d box = scene_bounds_over(kitchen, 0);
  EXPECT_GT((eye - box.center()).norm(), 0.5 * box.diagonal().norm());
}

// The bench's backrest swings forward (+y) into the table top: seen from the front.
TEST(WorkingSide, BenchTableIsSeenFromWhereTheBackrestSwings) {
  const scene::Reconfigurable bench = scene::load_scene(testing::source_dir() / "examples/bench-table/scene.json");
  const Camera camera = first_view(bench);
  EXPECT_GT(camera.eye().y(), camera.target.y());
}

scene::Reconfigurable sliding_box(const Eigen::Vector3d& out) {
  scene::Reconfigurable scene;
  scene.parts.emplace_back();
  scene.parts[0].name = "box";
  scene.parts[0].mesh = geometry::make_box(Eigen::Vector3d(1, 1, 1));
  scene.states.resize(2);
  scene.states[0].name = "in";
  scene.states[1].name = "out";
  scene.states[1].poses["box"].translation = out;
  return scene;
}

// Without transitions the states tell the side; a part moving toward −x is seen from −x
// (turned 30° for a three-quarter view), and a design that does not move gets the fixed view.
TEST(WorkingSide, StatesWithoutTransitionsAndStillDesigns) {
  Camera camera;
  aim_at_working_side(camera, sliding_box(Eigen::Vector3d(-1, 0, 0)));
  EXPECT_NEAR(camera.yaw, M_PI - M_PI / 6, 1e-9);
  EXPECT_LT(camera.eye().x() - camera.target.x(), 0);
  aim_at_working_side(camera, sliding_box(Eigen::Vector3d(0, 0, 1)));
  EXPECT_NEAR(camera.yaw, M_PI / 3, 1e-9);
  EXPECT_NEAR(camera.pitch, 25 * M_PI / 180, 1e-12);
}

}  // namespace
}  // namespace reconfig::view
