// The best view searched on its own thread: the same view as searched in place, only the latest
// request's result delivered, nothing after a cancel.

#include "view_search.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "reconfig/collision/detect_collisions.h"
#include "reconfig/render/best_view.h"
#include "reconfig/render/egl_context.h"
#include "reconfig/resolve/interval_energy.h"
#include "reconfig/scene/scene_file.h"
#include "reconfig/view/scene_bounds.h"
#include "support/test_data.h"

namespace reconfig::studio {
namespace {

struct BenchTable {
  std::shared_ptr<const scene::Reconfigurable> scene;
  int transition = 0;
  std::vector<collision::CollisionInterval> intervals;
};

const BenchTable& bench_table() {
  static const BenchTable table = [] {
    BenchTable t;
    auto scene = std::make_shared<scene::Reconfigurable>(
        scene::load_scene(testing::source_dir() / "examples" / "bench-table" / "scene.json"));
    collision::CollisionRequest request;
    const collision::CollisionResult found = collision::detect_collisions(*scene, request);
    for (const collision::TransitionCollisions& transition : found.transitions)
      if (!transition.intervals.empty() && t.intervals.empty()) {
        t.transition = transition.transition;
        t.intervals = transition.intervals;
      }
    t.scene = std::move(scene);
    return t;
  }();
  return table;
}

std::optional<ViewSearch::Result> wait_for(ViewSearch& search) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    if (std::optional<ViewSearch::Result> result = search.take()) return result;
    if (!search.busy()) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return std::nullopt;
}

TEST(ViewSearch, FindsTheViewSearchedInPlace) {
  const BenchTable& table = bench_table();
  ASSERT_FALSE(table.intervals.empty());
  const collision::CollisionInterval& interval = table.intervals.front();
  ViewSearch search;
  const std::uint64_t id = search.submit({table.scene, table.transition, interval, 0.7});
  const std::optional<ViewSearch::Result> found = wait_for(search);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->id, id);
  ASSERT_TRUE(found->error.empty()) << found->error;
  EXPECT_FALSE(search.busy());

  // In place, on this thread's own context.
  render::EglContext context;
  render::OcclusionCounter counter;
  resolve::ShapeCache shapes;
  const double time = resolve::interval_energy(*table.scene, shapes, table.transition, interval).severity_time;
  render::BestViewRequest request = render::interval_view_request(*table.scene, table.transition, interval, time);
  request.fov_y = 0.7;
  view::Camera camera = render::best_view(counter, *table.scene, request).camera;
  camera.fit_planes(view::scene_bounds_at(*table.scene, table.transition, time));
  EXPECT_DOUBLE_EQ(found->time, time);
  EXPECT_LT((found->camera.eye() - camera.eye()).norm(), 1e-12);
  EXPECT_LT((found->camera.target - camera.target).norm(), 1e-12);
  EXPECT_DOUBLE_EQ(found->camera.far_plane, camera.far_plane);
}

TEST(ViewSearch, DeliversOnlyTheLatestRequestAndNothingAfterACancel) {
  const BenchTable& table = bench_table();
  ASSERT_FALSE(table.intervals.empty());
  const collision::CollisionInterval& first = table.intervals.front();
  const collision::CollisionInterval& last = table.intervals.back();
  ViewSearch search;
  for (int round = 0; round < 3; ++round) {
    search.submit({table.scene, table.transition, first, 0.7});
    const std::uint64_t latest = search.submit({table.scene, table.transition, last, 0.7});
    const std::optional<ViewSearch::Result> found = wait_for(search);
    ASSERT_TRUE(found);
    EXPECT_EQ(found->id, latest);
    EXPECT_GE(found->time, last.t0 - 0.02);
    EXPECT_LE(found->time, last.t1 + 0.02);
    EXPECT_FALSE(search.take());  // once
  }
  search.submit({table.scene, table.transition, first, 0.7});
  EXPECT_TRUE(search.busy());
  search.cancel();
  EXPECT_FALSE(wait_for(search));  // the running one ends without a result
  EXPECT_FALSE(search.busy());
}

}  // namespace
}  // namespace reconfig::studio
