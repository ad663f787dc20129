#include "reconfig/collision/triangle_pair_ccd.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>

#include "reconfig/collision/ccd_primitives.h"
#include "reconfig/collision/coplanarity_cubic.h"
#include "reconfig/geometry/triangle_intersection.h"

namespace reconfig::collision {
namespace {

using Eigen::Vector3d;

constexpr int kContactTests = 15;  // 6 vertex–face + 9 edge–edge
/// Pieces longer than this (fraction of the step) are split wherever the coplanarity filter
/// cannot exclude a contact, without running the contact tests.
constexpr double kScreenedWidth = 1.0 / 32;

/// A piece of the (normalized) step, the contact tests that may still fire on it and where
/// their coplanarity cubics over it are stored: one per test, in the order of the tests,
/// from index `first_cubic` on.
struct Piece {
  double lo, hi;
  unsigned tests;
  std::size_t first_cubic;
};

struct Motion {
  std::array<Vector3d, 6> start, end;  // A's vertices 0..2, B's 3..5

  /// Position of vertex k at normalized time s, computed exactly as the contact tests'
  /// error analysis assumes.
  Vector3d at(int k, double s) const { return start[k] + s * (end[k] - start[k]); }
};

/// The points of contact test `index`: 0..2 A's vertex k vs B, 3..5 B's vertex k vs A, 6..14
/// A's edge i vs B's edge j (as indices of `Motion`).
std::array<int, 4> test_vertices(int index) {
  if (index < 3) return {index, 3, 4, 5};
  if (index < 6) return {index, 0, 1, 2};
  const int i = (index - 6) / 3, j = (index - 6) % 3;
  return {i, (i + 1) % 3, 3 + j, 3 + (j + 1) % 3};
}

/// Runs contact test `index` over [lo, hi].
bool may_touch(const Motion& m, int index, double lo, double hi, const PrimitiveCcdOptions& base) {
  PrimitiveCcdOptions options = base;
  options.t_min = lo;
  options.t_max = hi;
  const auto& s = m.start;
  const auto& e = m.end;
  const auto [p, a, b, c] = test_vertices(index);
  if (index < 6) return vertex_face_ccd(s[p], s[a], s[b], s[c], e[p], e[a], e[b], e[c], options).hit;
  return edge_edge_ccd(s[p], s[a], s[b], s[c], e[p], e[a], e[b], e[c], options).hit;
}

/// Whether the triangles' boxes over [lo, hi] are apart by more than the rounding of the
/// positions (a vertex's box over a time range is the box of its two end positions).
bool boxes_apart(const Motion& m, double lo, double hi, double margin) {
  Eigen::AlignedBox3d a, b;
  for (int k = 0; k < 6; ++k) {
    Eigen::AlignedBox3d& box = k < 3 ? a : b;
    box.extend(m.at(k, lo));
    box.extend(m.at(k, hi));
  }
  for (int i = 0; i < 3; ++i)
    if (a.min()[i] > b.max()[i] + margin || b.min()[i] > a.max()[i] + margin) return true;
  return false;
}

/// Whether the two primitives of contact test `index` (a vertex and a triangle, or two edges)
/// keep their boxes over the whole step apart by more than `margin` along some axis: then they
/// never touch, whatever the rounding of the positions, and the test cannot fire.
bool primitives_apart(const Motion& m, int index, double margin) {
  const auto [p, a, b, c] = test_vertices(index);
  Eigen::AlignedBox3d first, second;
  const auto add = [&](Eigen::AlignedBox3d& box, int k) {
    box.extend(m.start[k]);
    box.extend(m.end[k]);
  };
  add(first, p);  // vertex p and face a b c, or edge p a and edge b c
  add(index < 6 ? second : first, a);
  add(second, b);
  add(second, c);
  for (int i = 0; i < 3; ++i)
    if (first.min()[i] > second.max()[i] + margin || second.min()[i] > first.max()[i] + margin) return true;
  return false;
}

/// The buffers of one thread's calls (so `relevant` must not call `triangle_pair_ccd`).
struct Scratch {
  std::vector<Piece> queue;
  std::vector<CoplanarityCubic> cubics;
  std::vector<TimeInterval> found;
};

bool intersect_at(const Motion& m, double s) {
  return geometry::triangles_intersect(m.at(0, s), m.at(1, s), m.at(2, s), m.at(3, s), m.at(4, s), m.at(5, s));
}

}  // namespace

bool TrianglePairCcdResult::contains(double t) const {
  return std::any_of(intervals.begin(), intervals.end(),
                     [t](const TimeInterval& interval) { return interval.lo <= t && t <= interval.hi; });
}

TrianglePairCcdResult triangle_pair_ccd(const TrianglePairCcdRequest& request) {
  assert(request.t0 < request.t1 && request.distance_tolerance > 0 && request.time_tolerance >= 0);
  TrianglePairCcdResult result;
  Motion motion;
  double scale = 0;
  for (int k = 0; k < 6; ++k) {
    motion.start[k] = k < 3 ? request.a_start[k] : request.b_start[k - 3];
    motion.end[k] = k < 3 ? request.a_end[k] : request.b_end[k - 3];
    if (!motion.start[k].allFinite() || !motion.end[k].allFinite()) return result;
    scale = std::max({scale, motion.start[k].cwiseAbs().maxCoeff(), motion.end[k].cwiseAbs().maxCoeff()});
  }
  // Rounding of x0 + s (x1 − x0), twice (both triangles), with room to spare.
  const double box_margin = 4 * kRobustPerturbation * scale + 0x1p-1000;

  // Contact tests whose points never become coplanar on a piece are skipped outright
  // (`coplanarity_cubic.h`). A long piece where some may (strictly inside it) is halved
  // without running them (a contact test that cannot exclude its contact at once costs far
  // more than a halving); below `kScreenedWidth` they decide, as they stop the refinement
  // around false roots.
  if (boxes_apart(motion, 0, 1, box_margin)) {  // apart throughout: no cubic needed
    result.pieces = 1;
    return result;
  }
  // First in, first out (coarsest pieces first); `queue[next]` is the next piece. The
  // buffers are the thread's, kept from call to call (the detector makes thousands of calls).
  thread_local Scratch scratch;
  std::vector<Piece>& queue = scratch.queue;
  std::vector<CoplanarityCubic>& cubics = scratch.cubics;
  std::vector<TimeInterval>& found = scratch.found;  // in normalized time
  // Only the tests whose primitives come near each other somewhere in the step can fire.
  unsigned tests = 0;
  for (int index = 0; index < kContactTests; ++index)
    if (!primitives_apart(motion, index, box_margin)) tests |= 1u << index;
  queue.assign(1, Piece{0.0, 1.0, tests, 0});
  cubics.clear();
  found.clear();
  std::size_t next = 0;
  std::array<MovingPoints, kContactTests> points;
  for (int index = 0; index < kContactTests; ++index) {
    if (!(tests & (1u << index))) continue;
    const std::array<int, 4> vertices = test_vertices(index);
    for (int k = 0; k < 4; ++k) {
      points[index].start[k] = motion.start[vertices[k]];
      points[index].end[k] = motion.end[vertices[k]];
    }
    cubics.emplace_back(points[index], 0, 1);
  }
  PrimitiveCcdOptions options;
  options.tolerance = request.distance_tolerance;
  options.max_boxes = request.max_boxes;
  options.earliest = false;  // only whether, not when: the bisection finds the times

  while (next < queue.size()) {
    const Piece piece = queue[next++];
    ++result.pieces;
    if (boxes_apart(motion, piece.lo, piece.hi, box_margin)) continue;  // apart throughout

    std::array<std::size_t, kContactTests> slot{};  // where the cubic of each test of the piece is
    for (std::size_t index = 0, at = piece.first_cubic; index < kContactTests; ++index)
      if (piece.tests & (1u << index)) slot[index] = at++;
    const auto cubic_of = [&](int index) -> const CoplanarityCubic& { return cubics[slot[index]]; };
    unsigned coplanar = 0, at_an_end = 0;
    for (int index = 0; index < kContactTests; ++index) {
      if (!(piece.tests & (1u << index))) continue;
      const Coplanarity c = cubic_of(index).classify();
      if (c != Coplanarity::kNever) coplanar |= 1u << index;
      if (c == Coplanarity::kAtAnEnd) at_an_end |= 1u << index;
    }
    if (coplanar != 0 && request.relevant && !request.relevant(piece.lo, piece.hi)) continue;
    const double mid = 0.5 * (piece.lo + piece.hi);
    const bool can_split = piece.lo < mid && mid < piece.hi;
    const bool final_size = piece.hi - piece.lo <= request.time_tolerance || !can_split;
    if (coplanar != 0 && final_size) {
      // Reported whole if it holds an intersection; its ends are checked first, as they
      // usually settle that without looking for the contact.
      if (intersect_at(motion, piece.lo) || intersect_at(motion, piece.hi)) {
        found.push_back({piece.lo, piece.hi});
        continue;
      }
      bool touching = false;
      for (int index = 0; index < kContactTests && !touching; ++index) {
        if (!(coplanar & (1u << index))) continue;
        ++result.contact_tests;
        touching = may_touch(motion, index, piece.lo, piece.hi, options);
      }
      // Without a contact the status is that of the ends throughout: apart.
      if (touching) found.push_back({piece.lo, piece.hi});
      continue;
    }
    // Halving cannot separate a contact from the end of a piece: there the tests decide too.
    const unsigned screened = piece.hi - piece.lo <= kScreenedWidth ? coplanar : at_an_end;
    unsigned firing = coplanar & ~screened;
    for (int index = 0; index < kContactTests; ++index) {
      if (!(screened & (1u << index))) continue;
      ++result.contact_tests;
      if (may_touch(motion, index, piece.lo, piece.hi, options)) firing |= 1u << index;
    }
    if (firing == 0) {
      // No contact anywhere on the closed piece: one status throughout, robust to rounding.
      if (intersect_at(motion, mid)) found.push_back({piece.lo, piece.hi});
      continue;
    }
    if (static_cast<int>(queue.size()) >= request.max_pieces) {
      result.budget_exhausted = true;
      found.push_back({piece.lo, piece.hi});
      continue;
    }
    const std::size_t count = std::popcount(firing);
    queue.push_back({piece.lo, mid, firing, cubics.size()});
    queue.push_back({mid, piece.hi, firing, cubics.size() + count});
    cubics.resize(cubics.size() + 2 * count);
    // Halving by de Casteljau needs the exact middle; past 52 halvings it may be rounded.
    // (TwoSum: `sum` is exact iff its rounding error is zero.)
    const double sum = piece.lo + piece.hi, part = sum - piece.lo;
    const bool exact_middle = (piece.lo - (sum - part)) + (piece.hi - part) == 0 && sum > 0x1p-1000;
    std::size_t rank = 0;
    for (int index = 0; index < kContactTests; ++index)
      if (firing & (1u << index)) {
        const std::array<CoplanarityCubic, 2> halves =
            exact_middle ? cubic_of(index).halves()
                         : std::array{CoplanarityCubic(points[index], piece.lo, mid),
                                      CoplanarityCubic(points[index], mid, piece.hi)};
        cubics[queue.back().first_cubic - count + rank] = halves[0];
        cubics[queue.back().first_cubic + rank] = halves[1];
        ++rank;
      }
  }

  std::sort(found.begin(), found.end(), [](const TimeInterval& x, const TimeInterval& y) { return x.lo < y.lo; });
  const bool identity = request.t0 == 0 && request.t1 == 1;
  const double span = request.t1 - request.t0;
  for (const TimeInterval& piece : found) {
    TimeInterval t = piece;
    if (!identity) {  // map to [t0, t1], rounding outward
      t.lo = std::max(request.t0, std::nextafter(request.t0 + piece.lo * span, -HUGE_VAL));
      t.hi = std::min(request.t1, std::nextafter(request.t0 + piece.hi * span, HUGE_VAL));
      if (piece.lo == 0) t.lo = request.t0;
      if (piece.hi == 1) t.hi = request.t1;
    }
    if (request.merge_pieces && !result.intervals.empty() && t.lo <= result.intervals.back().hi)
      result.intervals.back().hi = std::max(result.intervals.back().hi, t.hi);
    else
      result.intervals.push_back(t);
  }
  return result;
}

}  // namespace reconfig::collision
