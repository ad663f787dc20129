#include "reconfig/collision/consolidate.h"

#include <gtest/gtest.h>

#include <random>

#include "reconfig/collision/interval_diff.h"

namespace reconfig::collision {
namespace {

Eigen::AlignedBox3d box(double x0, double x1) { return {Eigen::Vector3d(x0, 0, 0), Eigen::Vector3d(x1, 1, 1)}; }

TriangleContact contact(int a, int b, double t0, double t1, double x0, double x1, int tri = 0) {
  return {a, tri, b, tri, t0, t1, box(x0, x1), false};
}

TEST(Consolidate, MergesContactsOfOnePairThatMeetInTimeAndSpace) {
  const std::vector<TriangleContact> contacts = {
      contact(0, 1, 0.10, 0.20, 0, 1),
      contact(0, 1, 0.20, 0.30, 0.5, 1.5),  // adjacent in time, overlapping in space: merges
      contact(0, 1, 0.25, 0.28, 5, 6),      // overlaps in time but far away: separate
      contact(1, 2, 0.29, 0.35, 1.2, 2),    // meets the first group, but is another pair: separate
      contact(0, 1, 0.50, 0.60, 0, 1),      // later: separate
  };
  const std::vector<CollisionInterval> merged = consolidate(contacts, {});
  ASSERT_EQ(merged.size(), 4u);
  EXPECT_EQ(merged[0].t0, 0.10);
  EXPECT_EQ(merged[0].t1, 0.30);
  EXPECT_EQ(merged[0].parts, (std::vector<int>{0, 1}));
  EXPECT_EQ(merged[0].box.min().x(), 0);
  EXPECT_EQ(merged[0].box.max().x(), 1.5);
  EXPECT_EQ(merged[1].t0, 0.25);
  EXPECT_EQ(merged[2].parts, (std::vector<int>{1, 2}));
  EXPECT_EQ(merged[2].t1, 0.35);
  EXPECT_EQ(merged[3].t0, 0.50);
}

TEST(Consolidate, EachIntervalNamesOnePairOfParts) {
  // A bracket hit by two stools at one place and time (the kitchen after a gizmo edit): two
  // intervals, one per pair, not one of three parts.
  const std::vector<CollisionInterval> merged =
      consolidate({contact(0, 1, 0.2, 0.4, 0, 1), contact(0, 2, 0.3, 0.5, 0.5, 1.5)}, {});
  ASSERT_EQ(merged.size(), 2u);
  EXPECT_EQ(merged[0].parts, (std::vector<int>{0, 1}));
  EXPECT_EQ(merged[1].parts, (std::vector<int>{0, 2}));
}

TEST(Consolidate, BoundedDurationKeepsIntervalsShort) {
  std::vector<TriangleContact> contacts;
  for (int i = 0; i < 100; ++i) contacts.push_back(contact(0, 1, i * 0.01, (i + 1) * 0.01, 0, 1, i));
  EXPECT_EQ(consolidate(contacts, {}).size(), 1u);
  const auto frames = consolidate(contacts, {}, 0.05);
  EXPECT_GE(frames.size(), 20u);
  for (const CollisionInterval& ci : frames) EXPECT_LE(ci.duration(), 0.05 + 1e-12);
  double covered = 0;
  for (const CollisionInterval& ci : frames) covered += ci.duration();
  EXPECT_NEAR(covered, 1.0, 1e-9);  // nothing is lost
}

TEST(Consolidate, ContainmentsBecomeIntervals) {
  const std::vector<Containment> nested = {{2, 0, 0.4, 1.0, box(0, 1)}};
  const auto merged = consolidate({contact(0, 2, 0.3, 0.4, 0, 1)}, nested);
  ASSERT_EQ(merged.size(), 1u);
  EXPECT_TRUE(merged[0].containment);
  EXPECT_EQ(merged[0].t1, 1.0);
}

/// Property: every contact lies inside exactly one consolidated interval, whatever the order.
TEST(Consolidate, EveryContactIsCoveredByOneInterval) {
  std::mt19937 random(2);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<TriangleContact> contacts;
  for (int i = 0; i < 300; ++i) {
    const double t = unit(random), x = 10 * unit(random);
    contacts.push_back(contact(random() % 3, 3 + random() % 2, t, t + 0.02 * unit(random), x, x + unit(random), i));
  }
  for (double limit : {std::numeric_limits<double>::infinity(), 0.05}) {
    const auto merged = consolidate(contacts, {}, limit);
    for (const TriangleContact& c : contacts) {
      int holders = 0;
      for (const CollisionInterval& ci : merged)
        holders += std::count(ci.triangles.begin(), ci.triangles.end(),
                              std::array<int, 4>{c.part_a, c.triangle_a, c.part_b, c.triangle_b}) > 0 &&
                   ci.t0 <= c.t0 && c.t1 <= ci.t1 && ci.box.contains(c.box);
      EXPECT_EQ(holders, 1);
    }
    // No two intervals could still merge: they are of different pairs, do not meet in time and
    // space, or (bounded) together they would last longer than the limit.
    for (std::size_t i = 0; i < merged.size(); ++i)
      for (std::size_t j = i + 1; j < merged.size(); ++j)
        EXPECT_FALSE(merged[i].parts == merged[j].parts && merged[i].t0 <= merged[j].t1 && merged[j].t0 <= merged[i].t1 &&
                     merged[i].box.intersects(merged[j].box) &&
                     std::max(merged[i].t1, merged[j].t1) - std::min(merged[i].t0, merged[j].t0) <= limit);
  }
}

CollisionInterval ci(std::vector<int> parts, double t0, double t1) { return {t0, t1, std::move(parts), box(0, 1), false, false, {}}; }

TEST(IntervalDiff, ClassifiesAndOrdersByPriority) {
  const std::vector<CollisionInterval> before = {ci({0, 1}, 0.1, 0.2), ci({0, 2}, 0.3, 0.4), ci({1, 2}, 0.5, 0.6),
                                                 ci({0, 3}, 0.7, 0.9), ci({1, 3}, 0.1, 0.3)};
  const std::vector<CollisionInterval> after = {ci({0, 1}, 0.1, 0.2),     // unchanged
                                                ci({0, 2}, 0.3, 0.45),    // grew
                                                ci({0, 3}, 0.75, 0.8),    // shrank
                                                ci({2, 3}, 0.0, 0.05),    // appeared, short
                                                ci({2, 4}, 0.2, 0.6)};    // appeared, long
  // {1, 2} and {1, 3} disappeared.
  const auto diff = diff_intervals(before, after);
  ASSERT_EQ(diff.size(), 7u);
  EXPECT_EQ(diff[0].change, IntervalChange::kAppeared);
  EXPECT_EQ(diff[0].after->parts, (std::vector<int>{2, 4}));  // longer first
  EXPECT_EQ(diff[1].change, IntervalChange::kAppeared);
  EXPECT_EQ(diff[2].change, IntervalChange::kChanged);
  EXPECT_GT(diff[2].growth, 0);  // growing before shrinking
  EXPECT_EQ(diff[3].change, IntervalChange::kChanged);
  EXPECT_LT(diff[3].growth, 0);
  EXPECT_EQ(diff[4].change, IntervalChange::kDisappeared);
  EXPECT_EQ(diff[4].before->parts, (std::vector<int>{1, 3}));  // longer first
  EXPECT_EQ(diff[5].change, IntervalChange::kDisappeared);
  EXPECT_EQ(diff[6].change, IntervalChange::kUnchanged);
}

TEST(IntervalDiff, IdenticalSetsAreAllUnchanged) {
  const std::vector<CollisionInterval> set = {ci({0, 1}, 0.1, 0.2), ci({0, 1}, 0.5, 0.7)};
  for (const auto& entry : diff_intervals(set, set)) EXPECT_EQ(entry.change, IntervalChange::kUnchanged);
}

}  // namespace
}  // namespace reconfig::collision
