#include "reconfig/view/scene_bounds.h"

#include <gtest/gtest.h>

#include "reconfig/scene/scene_file.h"
#include "support/test_data.h"

namespace reconfig::view {
namespace {

TEST(SceneBounds, BenchTableBoundsContainEveryPosedVertex) {
  const scene::Reconfigurable scene = scene::load_scene(testing::source_dir() / "examples/bench-table/scene.json");
  const int unfold = scene.find_transition("unfold");
  ASSERT_GE(unfold, 0);
  const Eigen::AlignedBox3d at_half = scene_bounds_at(scene, unfold, 0.5);
  const Eigen::AlignedBox3d over = scene_bounds_over(scene, unfold);
  ASSERT_FALSE(at_half.isEmpty());
  EXPECT_TRUE(over.contains(at_half));
  EXPECT_TRUE(over.contains(scene_bounds_in_state(scene, scene.find_state("bench"))));
  for (int p = 0; p < static_cast<int>(scene.parts.size()); ++p) {
    const Eigen::MatrixX3d V = scene.posed_vertices(unfold, p, 0.5);
    for (int i = 0; i < V.rows(); ++i) EXPECT_TRUE(at_half.contains(V.row(i).transpose()));
  }
}

}  // namespace
}  // namespace reconfig::view
