// The broad phase (issue 25): per-pair work exists only for pairs of parts whose sweeps may
// meet, so 10,000 parts cost memory and time linear in the parts and the pairs found — every
// pair was kept before (10,000 far-apart boxes: 4.7 GB and 46 s).

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <chrono>
#include <set>

#include "collision/detail/spacetime_traversal.h"
#include "reconfig/collision/detect_collisions.h"
#include "reconfig/geometry/primitives.h"
#include "reconfig/scene/validate_scene.h"

namespace reconfig::collision {
namespace {

/// 10,000 unit cubes in rows of 100, 1.05 m apart along a row, the rows 3 m apart; each of
/// the first 100 even cubes slides 0.1 m into its (still) right neighbor.
scene::Reconfigurable crowd() {
  scene::Reconfigurable scene;
  scene::State start{"start", {}}, end{"end", {}};
  scene::Transition slide;
  slide.name = "slide";
  slide.from = "start";
  slide.to = "end";
  const geometry::Mesh cube = geometry::make_box({1, 1, 1});
  for (int k = 0; k < 10'000; ++k) {
    scene::Part part;
    part.name = "box_" + std::to_string(k);
    part.mesh = cube;
    part.source = scene::EditedMesh{};
    scene.parts.push_back(part);
    const Eigen::Vector3d a(1.05 * (k % 100), 3.0 * (k / 100), 0);
    const bool moves = k < 200 && k % 2 == 0;
    const Eigen::Vector3d b = a + Eigen::Vector3d(moves ? 0.1 : 0, 0, 0);
    start.poses[part.name] = {Eigen::Quaterniond::Identity(), a};
    end.poses[part.name] = {Eigen::Quaterniond::Identity(), b};
    if (moves) {
      scene::KeyframedTrack track;
      track.translation = {{0.0, a, a, a}, {1.0, b, b, b}};
      slide.tracks.emplace(part.name, track);
    }
  }
  scene.states = {start, end};
  scene.transitions = {slide};
  scene::validate_scene(scene);
  return scene;
}

long peak_memory_kb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

TEST(BroadPhase, TenThousandPartsCostMemoryLinearInThePairsThatMayMeet) {
  const scene::Reconfigurable scene = crowd();
  const auto start = std::chrono::steady_clock::now();
  const CollisionResult result = detect_collisions(scene);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::set<std::pair<int, int>> pairs;
  for (const CollisionInterval& interval : result.transitions[0].intervals)
    pairs.insert({interval.parts.front(), interval.parts.back()});
  EXPECT_EQ(pairs.size(), 100u);  // each sliding cube with its neighbor, and nothing else
  EXPECT_TRUE(pairs.contains({0, 1}));
  EXPECT_TRUE(pairs.contains({198, 199}));
  std::printf("[ broad    ] 10,000 parts, 100 moving: %.3f s, peak %ld MB\n", seconds, peak_memory_kb() / 1024);
  EXPECT_LT(peak_memory_kb(), 1L << 20) << "more than 1 GB";
}

TEST(BroadPhase, CandidatesAreExactlyThePairsWhoseSweepsMeet) {
  const scene::Reconfigurable scene = crowd();
  const BodyTrees trees = build_body_trees(scene);
  std::vector<PartProxy> proxies;
  for (int p = 0; p < static_cast<int>(scene.parts.size()); ++p) proxies.push_back(build_part_proxy(scene, 0, p, 1e-3));
  const std::vector<detail::TraversalRange> pairs = detail::candidate_pairs(trees, proxies, scene, DetectorOptions{});
  // Each cube's sweep meets its row neighbors' only where one slides 0.1 m into the next: the
  // 100 sliding pairs, and no others (cubes 0.05 m apart, rows 2 m apart).
  ASSERT_EQ(pairs.size(), 100u);
  for (const detail::TraversalRange& r : pairs) {
    EXPECT_EQ(r.b, r.a + 1);
    EXPECT_EQ(r.a % 2, 0);
    EXPECT_EQ(r.t0, 0.0);
    EXPECT_EQ(r.t1, 1.0);
  }
}

}  // namespace
}  // namespace reconfig::collision
