// The threads' bound caches, shared by every search: a search gets the bounds of its own inputs
// (as `TraversalInputs::node_bound` computes them), never those another search left behind
// under the same pair, node and samples.

#include "collision/detail/bound_cache.h"

#include <gtest/gtest.h>

#include "collision/detail/pair_timeline.h"
#include "support/random_scene.h"

namespace reconfig::collision::detail {
namespace {

constexpr DopFamily kFamily = DopFamily::k28;

/// What one search reads: a random scene's first two parts over the whole transition.
struct Search {
  scene::Reconfigurable scene;
  BodyTrees trees;
  std::vector<PartProxy> proxies;
  DetectorOptions options;

  explicit Search(std::uint32_t seed) : scene(testing::random_scene(seed)), trees(build_body_trees(scene)) {
    for (int p = 0; p < static_cast<int>(scene.parts.size()); ++p) proxies.push_back(build_part_proxy(scene, 0, p, 1e-3));
  }
  TraversalInputs<kFamily> inputs() const {
    return TraversalInputs<kFamily>(scene, trees, proxies, options, {merged_timeline(proxies, 0, 1, 0.0, 1.0)}, 1e-12);
  }
};

void expect_same(const Kdop<kFamily>& x, const Kdop<kFamily>& y) {
  EXPECT_EQ(x.lo, y.lo);
  EXPECT_EQ(x.hi, y.hi);
}

TEST(BoundCache, EachSearchGetsTheBoundsOfItsOwnInputs) {
  const Search first(3), second(4);
  const TraversalInputs<kFamily> a = first.inputs(), b = second.inputs();
  const std::uint64_t search_a = new_search_id(), search_b = new_search_id();
  EXPECT_NE(search_a, search_b);
  BoundCache<kFamily>& cache = thread_bound_cache<kFamily>();
  EXPECT_EQ(&cache, &thread_bound_cache<kFamily>());  // one per thread
  const int steps = static_cast<int>(std::min(a.lines[0].times.size(), b.lines[0].times.size())) - 1;
  ASSERT_GE(steps, 1);
  for (int round = 0; round < 2; ++round)  // the second round finds the first's bounds cached
    for (int side = 0; side < 2; ++side)
      for (const int node : {int{BodyTree::kRoot}, 1, 2})
        for (const auto& [s0, s1] : {std::pair{0, 1}, std::pair{0, steps}}) {
          std::array<Kdop<kFamily>, 2> ends_a, ends_b;
          const Kdop<kFamily> dop_a = a.node_bound(0, side, node, s0, s1, &ends_a);
          const Kdop<kFamily> dop_b = b.node_bound(0, side, node, s0, s1, &ends_b);
          // The two searches in turn, under the same key but for the search.
          const auto& from_a = cache.get(a, search_a, 0, side, node, s0, s1);
          expect_same(from_a.dop, dop_a);
          if (s1 - s0 == 1) expect_same(from_a.ends[1], ends_a[1]);
          const auto& from_b = BoundLookup<kFamily>{cache, search_b}.get(b, 0, side, node, s0, s1);
          expect_same(from_b.dop, dop_b);
          if (s1 - s0 == 1) expect_same(from_b.ends[0], ends_b[0]);
          EXPECT_NE(dop_a.lo, dop_b.lo);  // the scenes differ: so would a bound served to the wrong one
        }
}

}  // namespace
}  // namespace reconfig::collision::detail
