#include "reconfig/collision/triangle_pair_ccd.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <deque>

#include "reconfig/collision/ccd_primitives.h"
#include "reconfig/geometry/triangle_intersection.h"

namespace reconfig::collision {
namespace {

using Eigen::Vector3d;

constexpr int kContactTests = 15;  // 6 vertex–face + 9 edge–edge
constexpr unsigned kAllTests = (1u << kContactTests) - 1;

/// A piece of the (normalized) step and the contact tests that may still fire on it.
struct Piece {
  double lo, hi;
  unsigned tests;
};

struct Motion {
  std::array<Vector3d, 6> start, end;  // A's vertices 0..2, B's 3..5

  /// Position of vertex k at normalized time s, computed exactly as the contact tests'
  /// error analysis assumes.
  Vector3d at(int k, double s) const { return start[k] + s * (end[k] - start[k]); }
};

/// Runs contact test `index` over [lo, hi]: 0..2 A's vertex k vs B, 3..5 B's vertex k vs A,
/// 6..14 A's edge i vs B's edge j.
bool may_touch(const Motion& m, int index, double lo, double hi, const PrimitiveCcdOptions& base) {
  PrimitiveCcdOptions options = base;
  options.t_min = lo;
  options.t_max = hi;
  const auto& s = m.start;
  const auto& e = m.end;
  if (index < 3) return vertex_face_ccd(s[index], s[3], s[4], s[5], e[index], e[3], e[4], e[5], options).hit;
  if (index < 6) {
    const int k = index;
    return vertex_face_ccd(s[k], s[0], s[1], s[2], e[k], e[0], e[1], e[2], options).hit;
  }
  const int i = (index - 6) / 3, j = (index - 6) % 3;
  const int a0 = i, a1 = (i + 1) % 3, b0 = 3 + j, b1 = 3 + (j + 1) % 3;
  return edge_edge_ccd(s[a0], s[a1], s[b0], s[b1], e[a0], e[a1], e[b0], e[b1], options).hit;
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

  PrimitiveCcdOptions options;
  options.tolerance = request.distance_tolerance;
  options.max_boxes = request.max_boxes;
  options.earliest = false;  // only whether, not when: the bisection finds the times

  std::vector<TimeInterval> found;  // in normalized time
  std::deque<Piece> queue{{0.0, 1.0, kAllTests}};
  while (!queue.empty()) {
    const Piece piece = queue.front();
    queue.pop_front();
    ++result.pieces;
    if (boxes_apart(motion, piece.lo, piece.hi, box_margin)) continue;  // apart throughout

    unsigned firing = 0;
    for (int index = 0; index < kContactTests; ++index) {
      if (!(piece.tests & (1u << index))) continue;
      ++result.contact_tests;
      if (may_touch(motion, index, piece.lo, piece.hi, options)) firing |= 1u << index;
    }
    if (firing == 0) {
      // No contact anywhere on the closed piece: one status throughout, robust to rounding.
      if (intersect_at(motion, 0.5 * (piece.lo + piece.hi))) found.push_back({piece.lo, piece.hi});
      continue;
    }
    const double mid = 0.5 * (piece.lo + piece.hi);
    const bool can_split = piece.lo < mid && mid < piece.hi;
    if (piece.hi - piece.lo <= request.time_tolerance || !can_split) {
      found.push_back({piece.lo, piece.hi});
      continue;
    }
    if (result.pieces + static_cast<int>(queue.size()) >= request.max_pieces) {
      result.budget_exhausted = true;
      found.push_back({piece.lo, piece.hi});
      continue;
    }
    queue.push_back({piece.lo, mid, firing});
    queue.push_back({mid, piece.hi, firing});
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
    if (!result.intervals.empty() && t.lo <= result.intervals.back().hi)
      result.intervals.back().hi = std::max(result.intervals.back().hi, t.hi);
    else
      result.intervals.push_back(t);
  }
  return result;
}

}  // namespace reconfig::collision
