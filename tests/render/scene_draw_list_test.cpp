#include "reconfig/render/scene_draw_list.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "reconfig/common/input_error.h"
#include "reconfig/scene/scene_file.h"
#include "reconfig/view/picking.h"
#include "reconfig/view/scene_bounds.h"
#include "render_fixture.h"
#include "support/test_data.h"

namespace reconfig::render {
namespace {

using testing::color_distance;
using testing::RenderTest;

constexpr int kWidth = 200, kHeight = 150;

scene::Reconfigurable bench_table() {
  return scene::load_scene(reconfig::testing::source_dir() / "examples/bench-table/scene.json");
}

TEST(SceneDrawList, PartsGhostsBoxesAndGrid) {
  const scene::Reconfigurable scene = bench_table();
  const int unfold = scene.find_transition("unfold"), backrest = scene.find_part("backrest");
  SceneDrawRequest request;
  request.transition = unfold;
  request.time = 0.2;
  request.selected = {backrest};
  request.ghosts = view::ghost_samples({.current = 0.2, .count = 2, .spacing = 0.3});  // 0.5, 0.8
  request.boxes = {Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones())};
  const DrawList list = scene_draw_list(scene, request);
  const int parts = static_cast<int>(scene.parts.size());
  // Only the backrest moves in "unfold": one ghost per ghost time.
  ASSERT_EQ(static_cast<int>(list.meshes.size()), parts + 2);
  for (int p = 0; p < parts; ++p) {
    EXPECT_EQ(list.meshes[p].opacity, 1.0f);
    EXPECT_EQ(list.meshes[p].highlighted, p == backrest);
    EXPECT_TRUE(list.meshes[p].color.isApprox(scene.parts[p].color->cast<float>()));
  }
  EXPECT_TRUE(list.meshes[parts].V.isApprox(scene.posed_vertices(unfold, backrest, 0.5)));
  EXPECT_GT(list.meshes[parts].opacity, list.meshes[parts + 1].opacity);  // the farther ghost fades
  EXPECT_EQ(list.boxes.size(), 1u);
  EXPECT_TRUE(list.grid.visible);
  EXPECT_NEAR(list.grid.height, view::scene_bounds_at(scene, unfold, 0.2).min().z(), 1e-12);
}

TEST(SceneDrawList, GridSpacingIsANiceNumber) {
  EXPECT_DOUBLE_EQ(grid_spacing_for(1.3), 0.1);
  EXPECT_DOUBLE_EQ(grid_spacing_for(2.5), 0.2);
  EXPECT_DOUBLE_EQ(grid_spacing_for(40), 5);
  EXPECT_DOUBLE_EQ(grid_spacing_for(0.009), 0.001);
}

// Oracle: GPU-resident rest meshes placed by a matrix (and, for solids, without back faces)
// draw the same picture as meshes posed on the CPU, with ghosts, selection and a dragged part;
// the renderer drops a mesh whose object is gone (a new one at the same address is uploaded).
TEST_F(RenderTest, ResidentMeshesDrawWhatPosedMeshesDraw) {
  const scene::Reconfigurable scene = bench_table();
  SceneDrawRequest request;
  request.transition = scene.find_transition("unfold");
  request.time = 0.35;
  request.selected = {scene.find_part("seat")};
  request.ghosts = view::ghost_samples({.current = 0.35, .count = 2, .spacing = 0.2});
  motion::Pose dragged = scene.pose_at(request.transition, scene.find_part("armrest_left"), 0.35);
  dragged.translation.z() += 0.2;
  request.pose_overrides = {{scene.find_part("armrest_left"), dragged}};
  view::Camera camera;
  camera.frame_all(view::scene_bounds_at(scene, request.transition, 0.35), double(kWidth) / kHeight);
  const Image posed = renderer().render(scene_draw_list(scene, request), camera, kWidth, kHeight);
  for (int round = 0; round < 2; ++round) {
    for (const scene::Part& part : scene.parts)
      request.resident_meshes.push_back(std::make_shared<const geometry::Mesh>(part.mesh));
    // The second round culls back faces: the parts are closed outward solids, so nothing changes.
    if (round == 1) request.solid_parts.assign(scene.parts.size(), true);
    const Image resident = renderer().render(scene_draw_list(scene, request), camera, kWidth, kHeight);
    int different = 0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) different += color_distance(posed.pixel(x, y), resident.pixel(x, y)) > 24;
    // Float rounding of a matrix product instead of pre-posed positions flips a few edge pixels.
    EXPECT_LT(different, kWidth * kHeight / 200) << "round " << round;
    request.resident_meshes.clear();
  }
}

TEST_F(RenderTest, GhostAppearsWhereThePartIsAtAnotherTime) {
  const scene::Reconfigurable scene = bench_table();
  const int unfold = scene.find_transition("unfold"), backrest = scene.find_part("backrest");
  view::Camera camera;
  camera.yaw = -1.1;
  camera.pitch = 0.5;
  camera.frame_all(view::scene_bounds_over(scene, unfold), static_cast<double>(kWidth) / kHeight);
  SceneDrawRequest request;
  request.transition = unfold;
  request.time = 0.0;
  request.grid = false;
  const Image solid = renderer().render(scene_draw_list(scene, request), camera, kWidth, kHeight);
  request.ghosts = {{1.0, 1.0}};
  request.ghost_opacity = 0.5f;
  const Image ghosted = renderer().render(scene_draw_list(scene, request), camera, kWidth, kHeight);

  const Eigen::MatrixX3d ghost_V = scene.posed_vertices(unfold, backrest, 1.0);
  const Eigen::MatrixX3i& F = scene.parts[backrest].mesh.F;
  int changed = 0, on_ghost = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      if (color_distance(solid.pixel(x, y), ghosted.pixel(x, y)) < 20) continue;
      ++changed;
      on_ghost += testing::hits_near(camera, kWidth, kHeight, x, y, ghost_V, F);
    }
  EXPECT_GT(changed, 200) << "the ghost should be visible";
  EXPECT_GT(on_ghost, 0.95 * changed) << "pixels changed where the ghost is not";
  // The backrest at t = 1 (folded down into the table top) covers pixels that are free at t = 0.
  bool found_free_pixel = false;
  for (int y = 0; y < kHeight && !found_free_pixel; ++y)
    for (int x = 0; x < kWidth && !found_free_pixel; ++x) {
      const view::Ray ray = view::ray_from_pixel(camera, kWidth, kHeight, x + 0.5, y + 0.5);
      if (!view::ray_mesh(ray, ghost_V, F)) continue;
      bool free = true;
      for (int p = 0; p < static_cast<int>(scene.parts.size()) && free; ++p)
        free = !view::ray_mesh(ray, scene.posed_vertices(unfold, p, 0.0), scene.parts[p].mesh.F);
      if (!free) continue;
      found_free_pixel = true;
      EXPECT_GT(color_distance(solid.pixel(x, y), ghosted.pixel(x, y)), 20) << "pixel " << x << "," << y;
    }
  EXPECT_TRUE(found_free_pixel);
}

TEST_F(RenderTest, WritesAPng) {
  const scene::Reconfigurable scene = bench_table();
  SceneDrawRequest request;
  request.state = scene.find_state("table");
  view::Camera camera;
  camera.frame_all(view::scene_bounds_in_state(scene, request.state), 4.0 / 3);
  const Image image = renderer().render(scene_draw_list(scene, request), camera, 64, 48);
  const auto path = reconfig::testing::fresh_temp_dir() / "table.png";
  write_png(path, image);
  std::ifstream file(path, std::ios::binary);
  char signature[8] = {};
  file.read(signature, 8);
  EXPECT_EQ(std::string(signature + 1, 3), "PNG");
  EXPECT_THROW(write_png(path.parent_path() / "missing-folder" / "x.png", image), InputError);
}

}  // namespace
}  // namespace reconfig::render
