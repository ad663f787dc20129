// The coplanarity cubic against exact rational arithmetic: a "never" must hold at every
// sampled time (and for points moved by the robust perturbation), and constructed coplanar
// times must never be excluded, also far from the origin.

#include "reconfig/collision/coplanarity_cubic.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "exact_rational.h"

namespace reconfig::collision {
namespace {

using Eigen::Vector3d;
using exact::lerp_exact;
using exact::orient_exact;

int exact_sign(const MovingPoints& p, const mpq_class& t) {
  return sgn(orient_exact(lerp_exact(p.start[0], p.end[0], t), lerp_exact(p.start[1], p.end[1], t),
                          lerp_exact(p.start[2], p.end[2], t), lerp_exact(p.start[3], p.end[3], t)));
}

/// The sign of the exact orientation at 33 equally spaced times of [lo, hi] if it is the same
/// nonzero sign at all of them, else 0.
int sampled_sign(const MovingPoints& p, double lo, double hi) {
  int sign = 0;
  for (int k = 0; k <= 32; ++k) {
    const mpq_class t = mpq_class(lo) + (mpq_class(hi) - mpq_class(lo)) * mpq_class(k, 32);
    const int s = exact_sign(p, t);
    if (s == 0 || (sign != 0 && s != sign)) return 0;
    sign = s;
  }
  return sign;
}

MovingPoints random_grid_points(std::mt19937& rng) {
  std::uniform_int_distribution<int> coord(-3, 3);
  MovingPoints p;
  for (int k = 0; k < 4; ++k) {
    p.start[k] = Vector3d(coord(rng), coord(rng), coord(rng));
    p.end[k] = Vector3d(coord(rng), coord(rng), coord(rng));
  }
  return p;
}

TEST(CoplanarityCubic, NeverHoldsAtEverySampledTimeOnIntegerGrids) {
  std::mt19937 rng(99);
  int never = 0, possible = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    const MovingPoints p = random_grid_points(rng);
    const double lo = (rng() % 8) / 8.0, hi = lo + (1 + rng() % 8) / 64.0;
    const Coplanarity c = CoplanarityCubic(p, lo, std::min(hi, 1.0)).classify();
    if (c == Coplanarity::kNever) {
      ++never;
      ASSERT_NE(sampled_sign(p, lo, std::min(hi, 1.0)), 0) << "trial " << trial;
    } else {
      ++possible;
    }
    if (c == Coplanarity::kInside) {
      EXPECT_NE(exact_sign(p, mpq_class(lo)), 0) << "trial " << trial;
      EXPECT_NE(exact_sign(p, mpq_class(std::min(hi, 1.0))), 0) << "trial " << trial;
    }
  }
  EXPECT_GT(never, 500);
  EXPECT_GT(possible, 100);
}

/// Halving five times (to 1/32, as the narrow phase does) keeps every verdict true: a half
/// said never coplanar holds one sign at every sample, a half said not coplanar at its ends is
/// not, and the halves agree with cubics computed afresh wherever those exclude.
TEST(CoplanarityCubic, HalvesKeepTheGuarantees) {
  std::mt19937 rng(5);
  int never = 0, inside = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const MovingPoints p = random_grid_points(rng);
    struct Range {
      double lo, hi;
      CoplanarityCubic cubic;
    };
    std::vector<Range> ranges = {{0, 1, CoplanarityCubic(p, 0, 1)}};
    for (int depth = 0; depth < 5; ++depth) {
      std::vector<Range> next;
      for (const Range& r : ranges) {
        const std::array<CoplanarityCubic, 2> halves = r.cubic.halves();
        const double mid = 0.5 * (r.lo + r.hi);
        next.push_back({r.lo, mid, halves[0]});
        next.push_back({mid, r.hi, halves[1]});
      }
      ranges = std::move(next);
      for (const Range& r : ranges) {
        const Coplanarity c = r.cubic.classify();
        if (c == Coplanarity::kNever) {
          ++never;
          ASSERT_NE(sampled_sign(p, r.lo, r.hi), 0) << "trial " << trial << " [" << r.lo << ", " << r.hi << "]";
        } else if (c == Coplanarity::kInside) {
          ++inside;
          EXPECT_NE(exact_sign(p, mpq_class(r.lo)), 0);
          EXPECT_NE(exact_sign(p, mpq_class(r.hi)), 0);
        }
      }
    }
  }
  EXPECT_GT(never, 250);
  EXPECT_GT(inside, 12);
}

/// A vertex crosses the plane of three others at t = 3/8 exactly (dyadic, so representable):
/// every range containing 3/8 keeps it, a range ending there says so; far from the origin too.
TEST(CoplanarityCubic, AKnownCoplanarTimeIsNeverExcluded) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (double offset : {0.0, 1e3, 1e7}) {
    for (int trial = 0; trial < 200; ++trial) {
      MovingPoints p;
      // Three points translating together in the plane z = offset + t / 4, and a fourth
      // going from z = offset + 3/4 to offset − 1: it crosses the plane at t = 3/8.
      const Vector3d shift(offset, -offset, offset);
      for (int k = 1; k < 4; ++k) {
        p.start[k] = shift + Vector3d(unit(rng), unit(rng), 0);
        p.end[k] = p.start[k] + Vector3d(0.5, -0.25, 0.25);
      }
      p.start[0] = shift + Vector3d(unit(rng), unit(rng), 0.75);
      p.end[0] = shift + Vector3d(unit(rng), unit(rng), -1);
      ASSERT_EQ(exact_sign(p, mpq_class(3, 8)), 0);
      for (const auto& [lo, hi] : {std::pair{0.0, 1.0}, std::pair{0.25, 0.5}, std::pair{0.375, 0.4},
                                   std::pair{0.3, 0.375}, std::pair{0.375, 0.375}}) {
        EXPECT_NE(CoplanarityCubic(p, lo, hi).classify(), Coplanarity::kNever) << offset << " [" << lo << ", " << hi << "]";
      }
      EXPECT_EQ(CoplanarityCubic(p, 0.375, 0.5).classify(), Coplanarity::kAtAnEnd);
      EXPECT_EQ(CoplanarityCubic(p, 0.25, 0.375).classify(), Coplanarity::kAtAnEnd);
    }
  }
}

/// A "never" survives moving every point by the robust perturbation (start and end alike).
TEST(CoplanarityCubic, NeverIsRobustToThePerturbationTheNarrowPhaseRoundsBy) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1, 1);
  int tested = 0;
  for (int trial = 0; trial < 400; ++trial) {
    // Nearly coplanar motions: a fourth point just off the plane of the first three, which
    // translate in it.
    MovingPoints p;
    const Vector3d motion(unit(rng), unit(rng), 0);
    for (int k = 0; k < 3; ++k) {
      p.start[k] = Vector3d(unit(rng), unit(rng), 0);
      p.end[k] = p.start[k] + motion;
    }
    const double gap = std::ldexp(1.0, -20 - static_cast<int>(rng() % 30));
    p.start[3] = Vector3d(unit(rng), unit(rng), gap);
    p.end[3] = p.start[3] + Vector3d(unit(rng), unit(rng), 0);
    if (CoplanarityCubic(p, 0, 1).classify() != Coplanarity::kNever) continue;
    ++tested;
    const double m = 2;  // bound on |coordinates|
    MovingPoints moved = p;
    for (int k = 0; k < 4; ++k)
      for (int i = 0; i < 3; ++i) {
        moved.start[k][i] += (rng() % 2 ? 1 : -1) * kRobustPerturbation * m;
        moved.end[k][i] += (rng() % 2 ? 1 : -1) * kRobustPerturbation * m;
      }
    EXPECT_NE(sampled_sign(moved, 0, 1), 0) << "trial " << trial;
    EXPECT_EQ(sampled_sign(moved, 0, 1), sampled_sign(p, 0, 1)) << "trial " << trial;
  }
  EXPECT_GT(tested, 40);
}

TEST(CoplanarityCubic, PersistentCoplanarityAndBadInput) {
  // Four points translating together in one plane: coplanar throughout.
  MovingPoints p;
  p.start = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0), Vector3d(1, 1, 0)};
  for (int k = 0; k < 4; ++k) p.end[k] = p.start[k] + Vector3d(1, 2, 3);
  EXPECT_EQ(CoplanarityCubic(p, 0, 1).classify(), Coplanarity::kAtAnEnd);
  EXPECT_EQ(CoplanarityCubic(p, 0.25, 0.5).classify(), Coplanarity::kAtAnEnd);
  // Lifted off the plane: never.
  p.start[3].z() = 1e-3;
  p.end[3].z() = 3 + 1e-3;
  EXPECT_EQ(CoplanarityCubic(p, 0, 1).classify(), Coplanarity::kNever);
  p.end[2].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(CoplanarityCubic(p, 0, 1).classify(), Coplanarity::kAtAnEnd);
  p.end[2].x() = 0x1p400;
  EXPECT_EQ(CoplanarityCubic(p, 0, 1).classify(), Coplanarity::kAtAnEnd);
}

}  // namespace
}  // namespace reconfig::collision
