#include "side_effects.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace reconfig::studio {
namespace {

using collision::CollisionInterval;
using collision::IntervalChange;
using collision::IntervalDiffEntry;

CollisionInterval interval(double t0, double t1, std::vector<int> parts) {
  CollisionInterval ci;
  ci.t0 = t0;
  ci.t1 = t1;
  ci.parts = std::move(parts);
  return ci;
}

IntervalDiffEntry appeared(const CollisionInterval& after) { return {IntervalChange::kAppeared, std::nullopt, after, 0}; }

IntervalDiffEntry changed(const CollisionInterval& before, const CollisionInterval& after) {
  return {IntervalChange::kChanged, before, after, after.duration() - before.duration()};
}

TEST(SideEffects, NewBeforeChangedLongerBeforeShorterGrowingBeforeShrinking) {
  const CollisionInterval long_new = interval(0.1, 0.5, {0, 1}), short_new = interval(0.6, 0.7, {2, 3});
  const CollisionInterval grown = interval(0.2, 0.4, {4, 5}), shrunk = interval(0.2, 0.9, {6, 7});
  std::vector<IntervalDiffEntry> changes = {
      changed(interval(0.2, 0.95, {6, 7}), shrunk),  // shrinking, long
      changed(interval(0.25, 0.35, {4, 5}), grown),  // growing, shorter
      {IntervalChange::kDisappeared, interval(0.1, 0.9, {8, 9}), std::nullopt, 0},
      {IntervalChange::kUnchanged, interval(0, 1, {1, 2}), interval(0, 1, {1, 2}), 0},
      appeared(short_new),
      appeared(long_new),
  };
  // Whatever order the diff lists them in.
  std::mt19937 random(3);
  for (int round = 0; round < 20; ++round) {
    std::shuffle(changes.begin(), changes.end(), random);
    EXPECT_EQ(most_critical_side_effect(changes, std::nullopt)->parts, long_new.parts);
    // Working on the long new one: the next is the short new one.
    EXPECT_EQ(most_critical_side_effect(changes, interval(0.3, 0.35, {0, 1}))->parts, short_new.parts);
  }
  // Only changed ones: growing before shrinking even when shorter.
  EXPECT_EQ(most_critical_side_effect({changed(interval(0.2, 0.95, {6, 7}), shrunk),
                                       changed(interval(0.25, 0.35, {4, 5}), grown)},
                                      std::nullopt)
                ->parts,
            grown.parts);
  // Two shrinking: the longer.
  EXPECT_EQ(most_critical_side_effect({changed(interval(0.1, 0.5, {0, 1}), interval(0.1, 0.3, {0, 1})),
                                       changed(interval(0.1, 0.9, {2, 3}), interval(0.1, 0.8, {2, 3}))},
                                      std::nullopt)
                ->parts,
            (std::vector<int>{2, 3}));
}

TEST(SideEffects, NoneWhenOnlyTheWorkedOnOneChangedOrThingsWentAway) {
  const CollisionInterval worked = interval(0.2, 0.4, {0, 1});
  EXPECT_FALSE(most_critical_side_effect({changed(worked, interval(0.25, 0.35, {0, 1}))}, worked));
  EXPECT_FALSE(most_critical_side_effect({{IntervalChange::kDisappeared, worked, std::nullopt, 0}}, std::nullopt));
  EXPECT_FALSE(most_critical_side_effect({}, std::nullopt));
  // The same parts elsewhere in time is another collision: a side effect.
  EXPECT_TRUE(most_critical_side_effect({appeared(interval(0.7, 0.8, {0, 1}))}, worked));
}

TEST(FocusedInterval, PrefersTheSelectedPartsThenTheOneUnderTheTime) {
  const std::vector<CollisionInterval> intervals = {interval(0.1, 0.2, {0, 1}), interval(0.3, 0.5, {1, 2}),
                                                    interval(0.6, 0.9, {3, 4})};
  EXPECT_EQ(focused_interval(intervals, 0.4, -1), 1);
  EXPECT_EQ(focused_interval(intervals, 0.55, -1), 2);  // nearest
  EXPECT_EQ(focused_interval(intervals, 0.8, 0), 0);    // part 0's only one
  EXPECT_EQ(focused_interval(intervals, 0.8, 1), 1);    // the nearer of part 1's
  EXPECT_EQ(focused_interval(intervals, 0.8, 7), 2);    // no interval of part 7: any part
  EXPECT_EQ(focused_interval({}, 0.5, -1), -1);
}

}  // namespace
}  // namespace reconfig::studio
