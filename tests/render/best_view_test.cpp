#include "reconfig/render/best_view.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "reconfig/view/box_view_camera.h"
#include "reconfig/view/scene_bounds.h"
#include "reconfig/view/view_candidates.h"
#include "render_fixture.h"
#include "view_scenes.h"

namespace reconfig::render {
namespace {

using testing::RenderTest;
using testing::SlidingBox;

constexpr double kDegree = M_PI / 180;

double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
}

// Box 0 slides along x, box 1 along y; they cross around the origin at t = 0.5 (different
// heights, so that no faces are coplanar). `slab` adds a still plate above them.
scene::Reconfigurable crossing_boxes(bool slab) {
  std::vector<SlidingBox> boxes = {{{0.4, 0.4, 0.3}, {-1, 0, 0}, {1, 0, 0}}, {{0.4, 0.4, 0.2}, {0.1, -1, 0}, {0.1, 1, 0}}};
  if (slab) boxes.push_back({{3, 3, 0.05}, {0, 0, 0.6}, {0, 0, 0.6}});
  return testing::sliding_boxes(boxes);
}

BestViewRequest crossing_request() {
  BestViewRequest request;
  request.ground = false;  // floating: from below is as good as from above
  request.time = 0.5;
  request.t0 = 0.35;
  request.t1 = 0.65;
  request.parts = {0, 1};
  request.box = Eigen::AlignedBox3d(Eigen::Vector3d(-0.1, -0.2, -0.1), Eigen::Vector3d(0.2, 0.2, 0.1));
  return request;
}

TEST_F(RenderTest, BestViewOfTwoCrossingMotionsLooksAlongZAndAvoidsASlabAbove) {
  OcclusionCounter counter;
  const BestView open = best_view(counter, crossing_boxes(false), crossing_request());
  EXPECT_TRUE(open.from_motion);
  EXPECT_EQ(open.candidates, 2);
  EXPECT_LT(std::min(angle_between(open.direction, Eigen::Vector3d::UnitZ()),
                     angle_between(open.direction, -Eigen::Vector3d::UnitZ())), 5 * kDegree)
      << open.direction.transpose();
  EXPECT_GT(open.pixels.visible, 0);
  EXPECT_EQ(open.pixels.visible, open.pixels.total);  // nothing else in the way

  const BestView covered = best_view(counter, crossing_boxes(true), crossing_request());
  EXPECT_TRUE(covered.from_motion);
  EXPECT_LT(angle_between(covered.direction, -Eigen::Vector3d::UnitZ()), 5 * kDegree) << covered.direction.transpose();
  EXPECT_LT(angle_between(-covered.camera.forward(), -Eigen::Vector3d::UnitZ()), 5 * kDegree);
  EXPECT_EQ(covered.pixels.visible, covered.pixels.total);
  // The slab is really in the way from above.
  const view::Camera above = view::box_view_camera(crossing_request().box, Eigen::Vector3d::UnitZ());
  EXPECT_EQ(counter.count(crossing_request().box, {above})[0].visible, 0);
}

TEST_F(RenderTest, BestViewSamplesWhenTheMotionsAreParallelOrOnePartHoldsStill) {
  OcclusionCounter counter;
  const scene::Reconfigurable parallel =
      testing::sliding_boxes({{{0.4, 0.4, 0.3}, {-1, 0, 0}, {1, 0, 0}}, {{0.4, 0.4, 0.2}, {1, 0.1, 0}, {-1, 0.1, 0}}});
  BestViewRequest request = crossing_request();
  request.ground = true;
  request.samples = 50;
  const BestView sampled = best_view(counter, parallel, request);
  EXPECT_FALSE(sampled.from_motion);
  EXPECT_EQ(sampled.candidates, 50 + 5);  // the random directions and ±x, ±y, +z
  EXPECT_GE(sampled.direction.z(), 0);    // on the northern hemisphere: the design stands on a ground
  const scene::Reconfigurable still =
      testing::sliding_boxes({{{0.4, 0.4, 0.3}, {-1, 0, 0}, {1, 0, 0}}, {{0.4, 0.4, 0.2}, {0, 0, 0}, {0, 0, 0}}});
  EXPECT_FALSE(best_view(counter, still, request).from_motion);
}

TEST_F(RenderTest, BestViewOfADesignOnTheGroundIsNotFromBelowTheFloor) {
  OcclusionCounter counter;
  BestViewRequest request = crossing_request();
  request.ground = true;
  const BestView open = best_view(counter, crossing_boxes(false), request);
  EXPECT_TRUE(open.from_motion);
  EXPECT_LT(angle_between(open.direction, Eigen::Vector3d::UnitZ()), 5 * kDegree);
  // Slab above, floor below: neither motion normal sees X, the hemisphere is sampled.
  const BestView covered = best_view(counter, crossing_boxes(true), request);
  EXPECT_FALSE(covered.from_motion);
  EXPECT_GE(covered.direction.z(), 0);
  EXPECT_GT(covered.pixels.visible, 0);
}

// Three parts meet; four plates stand around them. The chosen view shows, by the ray-cast
// oracle, at least as much of X as each axis view and as each of 100 other random views.
TEST_F(RenderTest, BestViewOfThreePartsBeatsAxisAndRandomViewsByTheOracle) {
  const scene::Reconfigurable scene = testing::sliding_boxes({
      {{0.4, 0.4, 0.3}, {-1, 0, 0}, {1, 0, 0}},
      {{0.4, 0.4, 0.2}, {0, -1, 0}, {0, 1, 0}},
      {{0.2, 0.2, 0.6}, {0, 0, -1}, {0, 0, 1}},
      {{0.05, 1.2, 0.8}, {0.45, 0.1, 0.1}, {0.45, 0.1, 0.1}},     // a plate on the +x side
      {{1.0, 0.05, 0.5}, {-0.1, -0.42, 0.2}, {-0.1, -0.42, 0.2}},  // one on the −y side
      {{0.7, 0.7, 0.04}, {0.2, 0.2, 0.5}, {0.2, 0.2, 0.5}},       // a lid above, off center
      {{0.3, 0.3, 0.3}, {-0.5, 0.4, -0.3}, {-0.5, 0.4, -0.3}},     // a block low on the −x +y side
  });
  BestViewRequest request;
  request.time = 0.5;
  request.t0 = 0.4;
  request.t1 = 0.6;
  request.parts = {0, 1, 2};
  request.box = Eigen::AlignedBox3d(Eigen::Vector3d(-0.1, -0.1, -0.1), Eigen::Vector3d(0.1, 0.1, 0.1));
  request.ground = false;
  OcclusionCounter counter;
  const BestView best = best_view(counter, scene, request);
  EXPECT_FALSE(best.from_motion);
  EXPECT_EQ(best.candidates, 1000 + 6);

  Eigen::MatrixX3d V;
  Eigen::MatrixX3i F;
  posed_occluders(scene, 0, request.time, request.parts, request.max_triangles, V, F);
  ASSERT_EQ(F.rows(), 4 * 12);
  const int resolution = counter.resolution();
  const long chosen = testing::ray_cast_count(best.camera, resolution, request.box, V, F).visible;
  const double slack = 4 + 0.02 * best.pixels.total;  // rasterization vs ray casting at silhouettes
  const double min_radius = 0.02 * view::scene_bounds_at(scene, 0, 0.5).diagonal().norm();
  long best_axis = 0, best_random = 0, least = 1 << 30;
  for (const Eigen::Vector3d& d : view::axis_view_directions(false)) {
    const auto count = testing::ray_cast_count(view::box_view_camera(request.box, d, 1, request.fov_y, min_radius),
                                               resolution, request.box, V, F);
    best_axis = std::max(best_axis, count.visible);
    least = std::min(least, count.visible);
  }
  for (const Eigen::Vector3d& d : view::random_view_directions(100, false, 12345)) {
    const auto count = testing::ray_cast_count(view::box_view_camera(request.box, d, 1, request.fov_y, min_radius),
                                               resolution, request.box, V, F);
    best_random = std::max(best_random, count.visible);
    least = std::min(least, count.visible);
  }
  EXPECT_LT(least, best_axis / 2);  // the plates do hide X from some sides
  EXPECT_GE(chosen + slack, best_axis);
  EXPECT_GE(chosen + slack, best_random);
  EXPECT_NEAR(chosen, best.pixels.visible, slack);
}

// Random plates around three meeting parts: the view chosen (its coverage ruling out most
// candidates uncounted) is the one counting every candidate picks, the first of the most
// visible.
TEST_F(RenderTest, BestViewIsTheOneThatCountingEveryCandidatePicks) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> place(-0.6, 0.6), size(0.05, 0.7);
  int pruned = 0, several_rounds = 0, hidden_somewhat = 0;
  for (int trial = 0; trial < 8; ++trial) {
    std::vector<SlidingBox> boxes = {{{0.4, 0.4, 0.3}, {-1, 0, 0}, {1, 0, 0}},
                                     {{0.4, 0.4, 0.2}, {0, -1, 0}, {0, 1, 0}},
                                     {{0.2, 0.2, 0.6}, {0, 0, -1}, {0, 0, 1}}};
    for (int k = 0; k < 3 + 2 * trial; ++k) {
      const Eigen::Vector3d at(place(random), place(random), place(random));
      boxes.push_back({Eigen::Vector3d(size(random), size(random), size(random)), at, at});
    }
    const scene::Reconfigurable scene = testing::sliding_boxes(boxes);
    BestViewRequest request;
    request.time = 0.5;
    request.t0 = 0.4;
    request.t1 = 0.6;
    request.parts = {0, 1, 2};
    request.box = Eigen::AlignedBox3d(Eigen::Vector3d(-0.1, -0.1, -0.1), Eigen::Vector3d(0.1, 0.1, 0.1));
    request.ground = false;
    request.samples = 300;
    request.seed = trial + 1;
    OcclusionCounter counter;
    const BestView chosen = best_view(counter, scene, request);

    // Every candidate counted, as best_view builds them.
    const double min_radius = 0.02 * view::scene_bounds_at(scene, 0, request.time).diagonal().norm();
    Eigen::MatrixX3d V;
    Eigen::MatrixX3i F;
    posed_occluders(scene, 0, request.time, request.parts, request.max_triangles, V, F, request.box.center(),
                    view::box_view_distance(request.box, request.fov_y, min_radius));
    counter.set_occluders(V, F);
    std::vector<Eigen::Vector3d> directions = view::axis_view_directions(false);
    for (const Eigen::Vector3d& d : view::random_view_directions(request.samples, false, request.seed))
      directions.push_back(d);
    std::vector<view::Camera> cameras;
    for (const Eigen::Vector3d& d : directions)
      cameras.push_back(view::box_view_camera(request.box, d, 1.0, request.fov_y, min_radius));
    const std::vector<OcclusionCount> counts = counter.count(request.box, cameras);
    std::size_t first_best = 0;
    for (std::size_t i = 1; i < counts.size(); ++i)
      if (counts[i].visible > counts[first_best].visible) first_best = i;

    ASSERT_EQ(chosen.candidates, static_cast<int>(directions.size()));
    EXPECT_TRUE(chosen.direction.isApprox(directions[first_best])) << "trial " << trial;
    EXPECT_EQ(chosen.pixels.visible, counts[first_best].visible) << "trial " << trial;
    EXPECT_EQ(chosen.pixels.total, counts[first_best].total) << "trial " << trial;
    pruned += chosen.counted < chosen.candidates;
    several_rounds += chosen.counted > 64;
    hidden_somewhat += counts[first_best].visible < counts[first_best].total;
  }
  EXPECT_GT(pruned, 0);           // coverage did rule candidates out
  EXPECT_GT(several_rounds, 0);   // and sometimes only after several rounds
  EXPECT_GT(hidden_somewhat, 0);  // some best views are partly hidden
}

}  // namespace
}  // namespace reconfig::render
