#include "reconfig/render/occlusion_counter.h"

#include <gtest/gtest.h>

#include <random>

#include "reconfig/view/box_view_camera.h"
#include "reconfig/view/view_candidates.h"
#include "render_fixture.h"
#include "view_scenes.h"

namespace reconfig::render {
namespace {

using testing::RenderTest;

constexpr int kResolution = 64;

// Pixel counts of the query against the ray-cast oracle, over random views of a box among
// random slabs; more cameras than one batch holds, so batches and tiles are exercised too.
TEST_F(RenderTest, OcclusionCountsMatchRayCastingOverRandomViews) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> place(-0.8, 0.8), size(0.05, 0.6);
  geometry::Mesh slabs;
  for (int i = 0; i < 6; ++i) {
    geometry::Mesh slab = geometry::make_box(Eigen::Vector3d(size(random), size(random), size(random)));
    slab.V.rowwise() += Eigen::RowVector3d(place(random), place(random), place(random));
    slab.F.array() += static_cast<int>(slabs.V.rows());
    slabs.V.conservativeResize(slabs.V.rows() + slab.V.rows(), 3);
    slabs.V.bottomRows(slab.V.rows()) = slab.V;
    slabs.F.conservativeResize(slabs.F.rows() + slab.F.rows(), 3);
    slabs.F.bottomRows(slab.F.rows()) = slab.F;
  }
  const Eigen::AlignedBox3d box(Eigen::Vector3d(-0.15, -0.1, -0.05), Eigen::Vector3d(0.15, 0.2, 0.1));
  OcclusionCounter counter(kResolution);
  counter.set_occluders(slabs.V, slabs.F);
  std::vector<view::Camera> cameras;
  for (const Eigen::Vector3d& d : view::random_view_directions(counter.batch_size() + 40, false, 9))
    cameras.push_back(view::box_view_camera(box, d));
  const std::vector<OcclusionCount> counts = counter.count(box, cameras);
  ASSERT_EQ(counts.size(), cameras.size());
  const std::vector<long> coverage = counter.coverage(box, cameras);
  ASSERT_EQ(coverage.size(), cameras.size());
  for (std::size_t i = 0; i < cameras.size(); ++i)
    EXPECT_EQ(coverage[i], counts[i].total) << "camera " << i;  // the same pixels, without occluders
  // Any few of them, in any order, count as they did among all.
  const std::vector<int> which = {counter.batch_size() + 3, 7, 3, counter.batch_size() + 7, 200};
  const std::vector<OcclusionCount> some = counter.count_selected(box, cameras, which, false);
  ASSERT_EQ(some.size(), which.size());
  for (std::size_t k = 0; k < which.size(); ++k) {
    EXPECT_EQ(some[k].visible, counts[which[k]].visible) << "camera " << which[k];
    EXPECT_EQ(some[k].total, 0);
  }
  int partly_hidden = 0;
  for (std::size_t i = 0; i < cameras.size(); i += 7) {  // the oracle is slow: every 7th
    const testing::RayCount oracle = testing::ray_cast_count(cameras[i], kResolution, box, slabs.V, slabs.F);
    ASSERT_GT(oracle.total, 100);
    EXPECT_NEAR(counts[i].total, oracle.total, 2 + 0.02 * oracle.total) << "camera " << i;
    EXPECT_NEAR(counts[i].visible, oracle.visible, 4 + 0.03 * oracle.total) << "camera " << i;
    partly_hidden += oracle.visible < oracle.total && oracle.visible > 0;
  }
  EXPECT_GT(partly_hidden, 3);  // the slabs do hide the box from some sides
}

TEST_F(RenderTest, OcclusionCountsAreTheWholeBoxWithoutOccludersAndNoneInsideOne) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d(-0.1, -0.1, -0.1), Eigen::Vector3d(0.1, 0.1, 0.1));
  OcclusionCounter counter(kResolution);
  const std::vector<view::Camera> cameras = {view::box_view_camera(box, Eigen::Vector3d::UnitX()),
                                             view::box_view_camera(box, Eigen::Vector3d(1, 1, 1))};
  for (const OcclusionCount& count : counter.count(box, cameras)) {
    EXPECT_GT(count.total, 200);
    EXPECT_EQ(count.visible, count.total);
  }
  // A shell around the box, between it and the eyes: every view of it is blocked.
  const geometry::Mesh shell = geometry::make_box(Eigen::Vector3d(0.5, 0.5, 0.5));
  counter.set_occluders(shell.V, shell.F);
  for (const OcclusionCount& count : counter.count(box, cameras)) {
    EXPECT_GT(count.total, 200);
    EXPECT_EQ(count.visible, 0);
  }
}

}  // namespace
}  // namespace reconfig::render
