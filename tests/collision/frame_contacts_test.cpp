// What the traversal knows of one pair of parts in one frame: contacts merged into groups, and
// the protrusion that lets it skip work (0 exactly when a confirmed group holds the work's
// time range and box) and orders the rest.

#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "collision/detail/frame_contacts.h"

namespace reconfig::collision::detail {
namespace {

Eigen::AlignedBox3d box(double x0, double y0, double z0, double x1, double y1, double z1) {
  return {Eigen::Vector3d(x0, y0, z0), Eigen::Vector3d(x1, y1, z1)};
}

TriangleContact contact(double t0, double t1, const Eigen::AlignedBox3d& where, bool possible = false) {
  TriangleContact c;
  c.part_b = 1;
  c.t0 = t0;
  c.t1 = t1;
  c.box = where;
  c.possible = possible;
  return c;
}

TEST(FrameContacts, ProtrusionIsInfiniteWithoutAConfirmedGroup) {
  FrameContacts frame(0.1);
  EXPECT_EQ(frame.protrusion(0, 1, box(0, 0, 0, 1, 1, 1)), std::numeric_limits<double>::infinity());
  frame.add(contact(0, 1, box(0, 0, 0, 1, 1, 1), /*possible=*/true));
  EXPECT_EQ(frame.protrusion(0.2, 0.3, box(0.2, 0.2, 0.2, 0.3, 0.3, 0.3)), std::numeric_limits<double>::infinity());
}

TEST(FrameContacts, ProtrusionIsRelativeToTheSizeOfWhatSticksOut) {
  FrameContacts frame(0.1);
  frame.add(contact(0.0, 1.0, box(0, 0, 0, 1, 1, 1)));
  // Inside, touching faces included: nothing to find.
  EXPECT_EQ(frame.protrusion(0.0, 1.0, box(0, 0, 0, 1, 1, 1)), 0.0);
  EXPECT_EQ(frame.protrusion(0.5, 0.5, box(0.5, 0.5, 0.5, 0.5, 0.5, 0.5)), 0.0);
  // 0.25 out along x: over the box's longest side.
  EXPECT_DOUBLE_EQ(frame.protrusion(0.0, 1.0, box(0.5, 0, 0, 1.25, 0.5, 0.5)), 0.25 / 0.75);
  EXPECT_DOUBLE_EQ(frame.protrusion(0.0, 1.0, box(-0.25, 0, 0, 0.25, 0.1, 0.1)), 0.25 / 0.5);
  // Out in time: over the time range's length.
  EXPECT_DOUBLE_EQ(frame.protrusion(0.5, 1.5, box(0, 0, 0, 1, 1, 1)), 0.5);
  // The larger of the two.
  EXPECT_DOUBLE_EQ(frame.protrusion(0.5, 1.5, box(0, 0, 0, 2.5, 1, 1)), 1.5 / 2.5);
  EXPECT_DOUBLE_EQ(frame.protrusion(0.5, 1.5, box(0, 0, 0, 1.5, 1, 1)), 0.5);
  // A point outside (no size to measure it by): as urgent as can be, but finite.
  const double point = frame.protrusion(0.5, 0.5, box(2, 2, 2, 2, 2, 2));
  EXPECT_GT(point, 1e300);
  EXPECT_LT(point, std::numeric_limits<double>::infinity());
}

TEST(FrameContacts, ProtrusionTakesTheGroupItSticksOutOfLeast) {
  FrameContacts frame(0.1);
  frame.add(contact(0.0, 1.0, box(0, 0, 0, 1, 1, 1)));
  frame.add(contact(0.0, 1.0, box(5, 0, 0, 6, 1, 1)));
  ASSERT_EQ(frame.groups().size(), 2u);  // 4 apart, more than the gap
  EXPECT_EQ(frame.protrusion(0.2, 0.8, box(5.2, 0.2, 0.2, 5.8, 0.8, 0.8)), 0.0);
  EXPECT_DOUBLE_EQ(frame.protrusion(0.0, 1.0, box(5.5, 0, 0, 6.5, 1, 1)), 0.5);
}

// Oracle: for random groups and queries, the protrusion is 0 exactly when some confirmed
// group's time range and box contain the query's, and it never grows when a contact is added
// (groups only grow), so pruning stays sound whatever order contacts arrive in.
TEST(FrameContacts, ProtrusionIsZeroExactlyWhenAGroupContainsTheQuery) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(0, 10), length(0, 2), time(0, 1);
  const auto random_box = [&] {
    const Eigen::Vector3d lo(coordinate(rng), coordinate(rng), coordinate(rng));
    return Eigen::AlignedBox3d(lo, lo + Eigen::Vector3d(length(rng), length(rng), length(rng)));
  };
  for (int trial = 0; trial < 200; ++trial) {
    FrameContacts frame(0.05);
    for (int n = 0; n < 12; ++n) {
      double t0 = time(rng), t1 = std::min(1.0, t0 + 0.3 * time(rng));
      Eigen::AlignedBox3d query = random_box();
      if (n % 2 == 1 && !frame.groups().empty()) {  // within a group, or just out of it
        const CollisionInterval& g = frame.groups()[rng() % frame.groups().size()];
        const double out = n % 4 == 1 ? 0.0 : 1e-9;
        t0 = g.t0 + 0.5 * time(rng) * (g.t1 - g.t0);
        t1 = std::min(g.t1 + (rng() % 3 == 0 ? out : 0.0), t0 + time(rng) * (g.t1 - t0));
        const auto inside = [&] {
          return Eigen::Vector3d(g.box.min() + g.box.sizes().cwiseProduct(Eigen::Vector3d(time(rng), time(rng), time(rng))));
        };
        const Eigen::Vector3d a = inside(), b = inside();
        query = Eigen::AlignedBox3d(a.cwiseMin(b), a.cwiseMax(b) + Eigen::Vector3d(rng() % 3 == 1 ? out : 0.0, 0, 0));
      }
      const double before = frame.protrusion(t0, t1, query);
      frame.add(contact(time(rng) * 0.5, 0.5 + time(rng) * 0.5, random_box(), n % 5 == 4));
      const double after = frame.protrusion(t0, t1, query);
      EXPECT_LE(after, before);
      bool contained = false;
      for (const CollisionInterval& g : frame.groups())
        contained = contained || (!g.possible && g.t0 <= t0 && t1 <= g.t1 && g.box.contains(query));
      EXPECT_EQ(after == 0, contained) << "trial " << trial << " contact " << n;
    }
  }
}

}  // namespace
}  // namespace reconfig::collision::detail
