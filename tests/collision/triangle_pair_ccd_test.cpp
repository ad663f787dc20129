// The narrow phase: constructed pairs with exactly known intersection times (checked in exact
// rational arithmetic), degenerate and persistent contacts, and a dense-sampling oracle with
// exact static tests on integer grids (every sampled hit must be reported).

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <random>

#include "reconfig/collision/triangle_pair_ccd.h"
#include "reconfig/geometry/triangle_intersection.h"
#include "exact_rational.h"

namespace reconfig::collision {
namespace {

using Eigen::Vector3d;
using Tri = std::array<Vector3d, 3>;

TrianglePairCcdRequest request(const Tri& a0, const Tri& a1, const Tri& b0, const Tri& b1) {
  TrianglePairCcdRequest r;
  r.a_start = a0, r.a_end = a1, r.b_start = b0, r.b_end = b1;
  return r;
}

Tri shifted(const Tri& t, const Vector3d& d) { return {t[0] + d, t[1] + d, t[2] + d}; }

using exact::orient_exact;
using exact::Q3;
using exact::lerp_exact;

constexpr double kTau = 1e-6;  // the default time tolerance (fraction of the step)

const Tri kBig = {Vector3d(-5, -5, 0), Vector3d(5, -5, 0), Vector3d(0, 5, 0)};  // still, z = 0

const Tri kFalling = {Vector3d(1, 1, 1), Vector3d(1.25, 1, 1.5), Vector3d(1, 1.25, 1.5)};

TEST(TrianglePairCcd, VertexEntersTheFaceAtOneThird) {
  const Tri a0 = kFalling;
  // A's lowest vertex has z = 1 − 3t, the other two z = 1.5 − 3t: A meets B's plane (inside
  // B) for t in [1/3, 1/2].
  const Tri a1 = shifted(a0, {0, 0, -3});
  const TrianglePairCcdResult r = triangle_pair_ccd(request(a0, a1, kBig, kBig));
  ASSERT_EQ(r.intervals.size(), 1u);
  EXPECT_LE(r.intervals[0].lo, 1.0 / 3);
  EXPECT_GE(r.intervals[0].lo, 1.0 / 3 - 2 * kTau);
  EXPECT_GE(r.intervals[0].hi, 0.5);
  EXPECT_LE(r.intervals[0].hi, 0.5 + 2 * kTau);
  EXPECT_FALSE(r.budget_exhausted);
  // The events, exactly: A's low vertex on B's plane at 1/3, the high ones at 1/2.
  const mpq_class first(1, 3), last(1, 2);
  EXPECT_EQ(orient_exact(lerp_exact(kBig[0], kBig[0], first), lerp_exact(kBig[1], kBig[1], first),
                         lerp_exact(kBig[2], kBig[2], first), lerp_exact(a0[0], a1[0], first)),
            0);
  EXPECT_EQ(orient_exact(lerp_exact(kBig[0], kBig[0], last), lerp_exact(kBig[1], kBig[1], last),
                         lerp_exact(kBig[2], kBig[2], last), lerp_exact(a0[1], a1[1], last)),
            0);
}

/// Refining down to the last bit of time (past the 52 halvings where the pieces' middles stay
/// exact, so the coplanarity cubics are rebuilt instead of halved) still brackets the events.
TEST(TrianglePairCcd, RefinementToTheLastBitStillBracketsTheEvents) {
  const Tri a0 = kFalling;
  TrianglePairCcdRequest req = request(a0, shifted(a0, {0, 0, -3}), kBig, kBig);
  req.time_tolerance = 0;
  req.max_pieces = 1 << 20;
  const TrianglePairCcdResult r = triangle_pair_ccd(req);
  ASSERT_EQ(r.intervals.size(), 1u);
  EXPECT_FALSE(r.budget_exhausted);
  EXPECT_GT(r.pieces, 2 * 53);  // it went deeper than the exact halvings
  EXPECT_LE(r.intervals[0].lo, 1.0 / 3);
  EXPECT_GE(r.intervals[0].lo, 1.0 / 3 - 1e-6);  // the contact tests accept 1e-6 of distance
  EXPECT_GE(r.intervals[0].hi, 0.5);
  EXPECT_LE(r.intervals[0].hi, 0.5 + 1e-6);
}

TEST(TrianglePairCcd, EdgesCrossAtOneHalfThenPierce) {
  // A in plane y = 0 hanging below its top edge on the x axis; B in plane x = 0 standing on its
  // bottom edge at z = 1 − 2t. The edges cross at t = 1/2; then B's edge pierces A until t = 1.
  const Tri a = {Vector3d(-1, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 0, -1)};
  const Tri b0 = {Vector3d(0, -1, 1), Vector3d(0, 1, 1), Vector3d(0, 0, 2)};
  const Tri b1 = shifted(b0, {0, 0, -2});
  const TrianglePairCcdResult r = triangle_pair_ccd(request(a, a, b0, b1));
  ASSERT_EQ(r.intervals.size(), 1u);
  EXPECT_LE(r.intervals[0].lo, 0.5);
  EXPECT_GE(r.intervals[0].lo, 0.5 - 2 * kTau);
  EXPECT_EQ(r.intervals[0].hi, 1.0);
  const mpq_class half(1, 2);
  EXPECT_EQ(orient_exact(lerp_exact(a[0], a[0], half), lerp_exact(a[1], a[1], half), lerp_exact(b0[0], b1[0], half),
                         lerp_exact(b0[1], b1[1], half)),
            0);
}

TEST(TrianglePairCcd, GrazingContactAtASingleInstant) {
  // A hangs below z = 0 in plane y = 0; B (points with y' = y(t) + z, z ≥ 0) slides along y and
  // touches A only at the origin, only at t = 1/2.
  const Tri a = {Vector3d(-1, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 0, -1)};
  const Tri b0 = {Vector3d(0, -1, 0), Vector3d(-1, 0, 1), Vector3d(1, 0, 1)};
  const Tri b1 = shifted(b0, {0, 2, 0});
  const TrianglePairCcdResult r = triangle_pair_ccd(request(a, a, b0, b1));
  ASSERT_EQ(r.intervals.size(), 1u);
  EXPECT_LE(r.intervals[0].lo, 0.5);
  EXPECT_GE(r.intervals[0].hi, 0.5);
  EXPECT_LE(r.intervals[0].hi - r.intervals[0].lo, 4 * kTau);
  EXPECT_TRUE(geometry::triangles_intersect(a[0], a[1], a[2], b0[0] + Vector3d(0, 1, 0), b0[1] + Vector3d(0, 1, 0),
                                            b0[2] + Vector3d(0, 1, 0)));
  // Passing 1e-3 further away: never touch.
  const Tri c0 = shifted(b0, {0, 0, 1e-3}), c1 = shifted(b1, {0, 0, 1e-3});
  EXPECT_FALSE(triangle_pair_ccd(request(a, a, c0, c1)).any());
}

TEST(TrianglePairCcd, TouchingAtTheStart) {
  // Sharing a vertex at t = 0, then A lifts away.
  const Tri a0 = {Vector3d(0, 0, 0), Vector3d(-1, 0, 1), Vector3d(0, -1, 1)};
  const Tri a1 = shifted(a0, {0, 0, 1});
  const TrianglePairCcdResult r = triangle_pair_ccd(request(a0, a1, kBig, kBig));
  ASSERT_EQ(r.intervals.size(), 1u);
  EXPECT_EQ(r.intervals[0].lo, 0.0);
  EXPECT_LE(r.intervals[0].hi, 2 * kTau);
}

TEST(TrianglePairCcd, CoplanarSlidingIsCoveredAndReportedWhole) {
  // B = A shifted by x(t) = −2 + 4t in A's plane: they share points for x in [−1, 1], i.e.
  // t in [1/4, 3/4], touching along edges throughout (persistent contact: refined only to the
  // piece budget).
  const Tri a = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0)};
  TrianglePairCcdRequest sliding = request(a, a, shifted(a, {-2, 0, 0}), shifted(a, {2, 0, 0}));
  sliding.max_pieces = 1024;
  const TrianglePairCcdResult r = triangle_pair_ccd(sliding);
  ASSERT_EQ(r.intervals.size(), 1u);
  EXPECT_TRUE(r.budget_exhausted);
  EXPECT_LE(r.intervals[0].lo, 0.25);
  EXPECT_GE(r.intervals[0].hi, 0.75);
  EXPECT_GE(r.intervals[0].lo, 0.25 - 1e-2);
  EXPECT_LE(r.intervals[0].hi, 0.75 + 1e-2);
  // Sliding 1e-3 above the plane: never.
  EXPECT_FALSE(triangle_pair_ccd(request(a, a, shifted(a, {-2, 0, 1e-3}), shifted(a, {2, 0, 1e-3}))).any());
}

TEST(TrianglePairCcd, ParallelMotionKeepsTheStatus) {
  const Vector3d v(3, -1, 2);
  // Interpenetrating transversally: one piece, intersecting throughout.
  const Tri a = {Vector3d(-1, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 0, -1)};
  const Tri b = {Vector3d(0, -1, -0.5), Vector3d(0, 1, -0.5), Vector3d(0, 0, 1)};
  const TrianglePairCcdResult inside = triangle_pair_ccd(request(a, shifted(a, v), b, shifted(b, v)));
  ASSERT_EQ(inside.intervals.size(), 1u);
  EXPECT_EQ(inside.intervals[0].lo, 0.0);
  EXPECT_EQ(inside.intervals[0].hi, 1.0);
  EXPECT_EQ(inside.pieces, 1);
  // Apart.
  const Tri c = shifted(b, {2, 0, 0});
  EXPECT_FALSE(triangle_pair_ccd(request(a, shifted(a, v), c, shifted(c, v))).any());
}

TEST(TrianglePairCcd, ZeroAreaTriangles) {
  // A collapsed to a segment falling through B from t = 1/4 (z = 1 − 4t ... 1.4 − 4t).
  const Tri a0 = {Vector3d(1, 1, 1), Vector3d(1, 1, 1.4), Vector3d(1, 1, 1.2)};
  const Tri a1 = shifted(a0, {0, 0, -4});
  const TrianglePairCcdResult r = triangle_pair_ccd(request(a0, a1, kBig, kBig));
  ASSERT_EQ(r.intervals.size(), 1u);
  EXPECT_NEAR(r.intervals[0].lo, 0.25, 2 * kTau);
  EXPECT_NEAR(r.intervals[0].hi, 0.35, 2 * kTau);
  // A collapsed to a point, and B collapsed to a point: they meet at t = 1/2 only.
  const Tri p0 = {Vector3d(0, 0, 0), Vector3d(0, 0, 0), Vector3d(0, 0, 0)};
  const Tri p1 = shifted(p0, {2, 2, 2});
  const Tri q0 = {Vector3d(2, 0, 0), Vector3d(2, 0, 0), Vector3d(2, 0, 0)};
  const Tri q1 = shifted(q0, {-2, 2, 2});
  const TrianglePairCcdResult points = triangle_pair_ccd(request(p0, p1, q0, q1));
  ASSERT_EQ(points.intervals.size(), 1u);
  EXPECT_LE(points.intervals[0].lo, 0.5);
  EXPECT_GE(points.intervals[0].hi, 0.5);
}

TEST(TrianglePairCcd, TimeStepIsMappedWithOutwardRounding) {
  const Tri a0 = kFalling;
  TrianglePairCcdRequest req = request(a0, shifted(a0, {0, 0, -3}), kBig, kBig);
  req.t0 = 2.0;
  req.t1 = 2.5;
  const TrianglePairCcdResult r = triangle_pair_ccd(req);
  ASSERT_EQ(r.intervals.size(), 1u);
  EXPECT_LE(r.intervals[0].lo, 2.0 + 0.5 / 3);
  EXPECT_GE(r.intervals[0].hi, 2.25);
  EXPECT_TRUE(r.contains(2.2));
  EXPECT_FALSE(r.contains(2.1));
}

// ---- randomized oracle ------------------------------------------------------------------------

constexpr int kSteps = 256;  // samples t = k / 256: exact positions for small integer coordinates

struct RandomPair {
  Tri a0, a1, b0, b1;
};

RandomPair random_grid_pair(std::mt19937& rng) {
  std::uniform_int_distribution<int> coord(-2, 2);
  auto point = [&] { return Vector3d(coord(rng), coord(rng), coord(rng)); };
  RandomPair p;
  for (int k = 0; k < 3; ++k) p.a0[k] = point(), p.a1[k] = point(), p.b0[k] = point(), p.b1[k] = point();
  switch (rng() % 6) {
    case 0:  // everything in one plane
      for (Tri* t : {&p.a0, &p.a1, &p.b0, &p.b1})
        for (Vector3d& x : *t) x.z() = 0;
      break;
    case 1:  // a degenerate triangle
      p.a0[2] = p.a0[1], p.a1[2] = p.a1[1];
      break;
    case 2:  // translations only
      for (int k = 1; k < 3; ++k) p.a1[k] = p.a0[k] + (p.a1[0] - p.a0[0]), p.b1[k] = p.b0[k] + (p.b1[0] - p.b0[0]);
      break;
    default:
      break;
  }
  return p;
}

bool sampled_hit(const RandomPair& p, int k) {
  const double t = static_cast<double>(k) / kSteps;
  Tri a, b;
  for (int i = 0; i < 3; ++i) a[i] = p.a0[i] + t * (p.a1[i] - p.a0[i]), b[i] = p.b0[i] + t * (p.b1[i] - p.b0[i]);
  return geometry::triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2]);
}

TEST(TrianglePairCcdOracle, EverySampledIntersectionIsReportedOnIntegerGrids) {
  std::mt19937 rng(314159);
  int hits = 0, misses = 0, partial = 0, exhausted = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const RandomPair p = random_grid_pair(rng);
    TrianglePairCcdRequest req = request(p.a0, p.a1, p.b0, p.b1);
    req.max_pieces = 128;  // keeps persistent contacts cheap; the oracle must still hold
    const TrianglePairCcdResult r = triangle_pair_ccd(req);
    exhausted += r.budget_exhausted;
    int sampled = 0;
    for (int k = 0; k <= kSteps; ++k) {
      const double t = static_cast<double>(k) / kSteps;
      const bool hit = sampled_hit(p, k);
      sampled += hit;
      if (hit) {
        ASSERT_TRUE(r.contains(t)) << "trial " << trial << " t " << t;
      }
      // No gross false positives: a sample well inside a reported interval intersects (unless
      // the piece budget ran out: undecided pieces are then reported whole).
      const bool deep = !r.budget_exhausted && std::any_of(r.intervals.begin(), r.intervals.end(), [&](const TimeInterval& i) {
        return i.lo + 2.0 / kSteps < t && t < i.hi - 2.0 / kSteps;
      });
      if (deep) {
        EXPECT_TRUE(hit) << "trial " << trial << " t " << t;
      }
    }
    if (sampled == kSteps + 1) ++hits;
    else if (sampled == 0) ++misses;
    else ++partial;
  }
  // The oracle is only meaningful if all kinds of outcome occur.
  EXPECT_GT(partial, 40);
  EXPECT_GT(misses, 40);
  EXPECT_GT(hits, 5);
  EXPECT_LT(exhausted, 200);  // persistent contacts (sliding, shared edges) exhaust it; most pairs do not
}

TEST(TrianglePairCcdOracle, RandomContinuousPairsMatchDenseSampling) {
  std::mt19937 rng(2718);
  std::uniform_real_distribution<double> coord(-1, 1);
  int partial = 0;
  for (int trial = 0; trial < 300; ++trial) {
    RandomPair p;
    for (int k = 0; k < 3; ++k) {
      p.a0[k] = Vector3d(coord(rng), coord(rng), coord(rng));
      p.b0[k] = Vector3d(coord(rng), coord(rng), coord(rng));
      p.a1[k] = p.a0[k] + 0.8 * Vector3d(coord(rng), coord(rng), coord(rng));
      p.b1[k] = p.b0[k] + 0.8 * Vector3d(coord(rng), coord(rng), coord(rng));
    }
    const TrianglePairCcdResult r = triangle_pair_ccd(request(p.a0, p.a1, p.b0, p.b1));
    EXPECT_FALSE(r.budget_exhausted);
    int sampled = 0;
    for (int k = 0; k <= kSteps; ++k) {
      // Positions are rounded here; away from the reported boundaries (by more than the time
      // tolerance) the rounded static test must agree with the report.
      const double t = static_cast<double>(k) / kSteps;
      const bool hit = sampled_hit(p, k);
      sampled += hit;
      bool near_boundary = false;
      for (const TimeInterval& i : r.intervals)
        near_boundary |= std::abs(t - i.lo) < 1e-3 || std::abs(t - i.hi) < 1e-3;
      if (!near_boundary) {
        EXPECT_EQ(hit, r.contains(t)) << "trial " << trial << " t " << t;
      }
    }
    partial += sampled > 0 && sampled <= kSteps;
  }
  EXPECT_GT(partial, 20);
}

/// Small triangles passing through each other or sliding by, as in deep interpenetrations: a
/// third of them (by `trial`) moving nearly together, intersecting (or not) all along.
RandomPair passing_pair(std::mt19937& rng, int trial) {
  std::uniform_real_distribution<double> coord(-1, 1);
  RandomPair p;
  const Vector3d a_motion = 0.2 * Vector3d(coord(rng), coord(rng), coord(rng));
  // A third of the pairs move nearly together: intersecting (or not) all along.
  const bool together = trial % 3 == 0;
  const Vector3d b_motion = together ? Vector3d(a_motion + 0.002 * Vector3d(coord(rng), coord(rng), coord(rng)))
                                     : Vector3d(0.2 * Vector3d(coord(rng), coord(rng), coord(rng)));
  const Vector3d a_center = 0.05 * Vector3d(coord(rng), coord(rng), coord(rng)) - a_motion / 2;
  const Vector3d b_center = together ? Vector3d(a_center + 0.01 * Vector3d(coord(rng), coord(rng), coord(rng)))
                                     : Vector3d(0.05 * Vector3d(coord(rng), coord(rng), coord(rng)) - b_motion / 2);
  // A little rotation: the vertices do not all move alike.
  const double turn = together ? 0.0 : 0.05 * coord(rng);
  for (int k = 0; k < 3; ++k) {
    const Vector3d da = 0.03 * Vector3d(coord(rng), coord(rng), coord(rng));
    const Vector3d db = 0.03 * Vector3d(coord(rng), coord(rng), coord(rng));
    p.a0[k] = a_center + da;
    p.a1[k] = a_center + a_motion + da + turn * Vector3d(-da.y(), da.x(), 0);
    p.b0[k] = b_center + db;
    p.b1[k] = b_center + b_motion + db;
  }
  return p;
}

/// The detector's settings (1/32 of the step, 1e-4): small triangles passing through each other
/// or sliding by, as in deep interpenetrations. Every sampled intersection is reported; a piece
/// decided by one static test really holds that status at every sample; a reported interval
/// holds an intersection except within one final piece of its ends.
TEST(TrianglePairCcdOracle, DetectorSettingsOnPassingTriangles) {
  std::mt19937 rng(1618);
  constexpr double kPiece = 1.0 / 32;
  int whole = 0, partial = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const RandomPair p = passing_pair(rng, trial);
    TrianglePairCcdRequest req = request(p.a0, p.a1, p.b0, p.b1);
    req.time_tolerance = kPiece;
    req.distance_tolerance = 1e-4;
    const TrianglePairCcdResult r = triangle_pair_ccd(req);
    EXPECT_FALSE(r.budget_exhausted);
    const bool one_status = r.pieces == 1;  // decided by one static test, no contact possible
    int sampled = 0;
    for (int k = 0; k <= kSteps; ++k) {
      const double t = static_cast<double>(k) / kSteps;
      const bool hit = sampled_hit(p, k);
      sampled += hit;
      if (hit) {
        ASSERT_TRUE(r.contains(t)) << "trial " << trial << " t " << t;
      }
      if (one_status) {
        EXPECT_EQ(hit, r.any()) << "trial " << trial << " t " << t;
      }
      const bool deep = std::any_of(r.intervals.begin(), r.intervals.end(), [&](const TimeInterval& i) {
        return i.lo + kPiece < t && t < i.hi - kPiece;
      });
      if (deep) {
        EXPECT_TRUE(hit) << "trial " << trial << " t " << t;
      }
    }
    whole += one_status && r.any();
    partial += sampled > 0 && sampled <= kSteps;
  }
  EXPECT_GT(whole, 5) << partial;
  EXPECT_GT(partial, 40) << whole;
}

/// The detector's use: pieces it rejects are left out, with their halves, and every other
/// piece is reported as without the rejection; unmerged, the pieces reported are those whose
/// union the merged answer is.
TEST(TrianglePairCcdOracle, RejectedPiecesAreLeftOutAndTheRestIsReportedAsWithout) {
  std::mt19937 rng(4242);
  std::uniform_int_distribution<int> sixty_fourth(0, 64);
  const auto same = [](const TimeInterval& x, const TimeInterval& y) { return x.lo == y.lo && x.hi == y.hi; };
  int dropped = 0, kept = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const RandomPair p = passing_pair(rng, trial);
    TrianglePairCcdRequest req = request(p.a0, p.a1, p.b0, p.b1);
    req.time_tolerance = 1.0 / 32;
    req.distance_tolerance = 1e-4;
    const TrianglePairCcdResult merged = triangle_pair_ccd(req);
    req.merge_pieces = false;
    const TrianglePairCcdResult pieces = triangle_pair_ccd(req);
    // Merging the touching pieces gives the merged answer.
    std::vector<TimeInterval> united;
    for (const TimeInterval& i : pieces.intervals) {
      ASSERT_LE(i.lo, i.hi);
      if (!united.empty()) {
        ASSERT_LE(united.back().hi, i.lo) << "trial " << trial;
      }
      if (!united.empty() && i.lo <= united.back().hi) united.back().hi = std::max(united.back().hi, i.hi);
      else united.push_back(i);
    }
    ASSERT_EQ(united.size(), merged.intervals.size()) << "trial " << trial;
    for (std::size_t k = 0; k < united.size(); ++k) EXPECT_TRUE(same(united[k], merged.intervals[k])) << "trial " << trial;

    // Reject every piece within a random window.
    double w0 = sixty_fourth(rng) / 64.0, w1 = sixty_fourth(rng) / 64.0;
    if (w0 > w1) std::swap(w0, w1);
    int asked = 0;
    req.relevant = [&](double lo, double hi) {
      ++asked;
      return !(w0 <= lo && hi <= w1);
    };
    const TrianglePairCcdResult part = triangle_pair_ccd(req);
    EXPECT_LE(part.pieces, pieces.pieces);
    if (pieces.pieces > 1) {
      EXPECT_GT(asked, 0) << "trial " << trial;
    }
    for (const TimeInterval& i : part.intervals)
      EXPECT_TRUE(std::any_of(pieces.intervals.begin(), pieces.intervals.end(), [&](const TimeInterval& j) { return same(i, j); }))
          << "trial " << trial << ": [" << i.lo << ", " << i.hi << "] was not reported without the rejection";
    for (const TimeInterval& j : pieces.intervals) {
      const bool reported = std::any_of(part.intervals.begin(), part.intervals.end(), [&](const TimeInterval& i) { return same(i, j); });
      if (!(w0 <= j.lo && j.hi <= w1)) {
        EXPECT_TRUE(reported) << "trial " << trial << ": [" << j.lo << ", " << j.hi << "] lies outside the window";
      }
      dropped += !reported;
      kept += reported;
    }
  }
  EXPECT_GT(dropped, 50);  // the rejection mattered
  EXPECT_GT(kept, 50);
}

}  // namespace
}  // namespace reconfig::collision
