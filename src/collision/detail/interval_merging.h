#pragma once
/// @file
/// When two collision intervals merge, and what merging does: shared by consolidation and by
/// the detector's per-frame contact groups, which must merge by the same rule.

#include <algorithm>

#include "reconfig/collision/collision_interval.h"

namespace reconfig::collision::detail {

inline constexpr double kAdjacent = 1e-12;  ///< time gap under which two extents count as touching

/// Whether the boxes overlap, or come closer than `gap` on every axis.
inline bool boxes_meet(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b, double gap = 0) {
  return (a.min().array() <= b.max().array() + gap).all() && (b.min().array() <= a.max().array() + gap).all();
}

inline bool times_meet(const CollisionInterval& a, const CollisionInterval& b) {
  return a.t0 <= b.t1 + kAdjacent && b.t0 <= a.t1 + kAdjacent;
}

/// Two intervals merge when they meet both in time and in space (their boxes within `gap`).
inline bool intervals_meet(const CollisionInterval& a, const CollisionInterval& b, double gap = 0) {
  return times_meet(a, b) && boxes_meet(a.box, b.box, gap);
}

inline void add_part(std::vector<int>& parts, int part) {
  const auto at = std::lower_bound(parts.begin(), parts.end(), part);
  if (at == parts.end() || *at != part) parts.insert(at, part);
}

/// Grows `into` by `other`: time hull, box hull, parts, flags and triangle pairs.
inline void absorb(CollisionInterval& into, const CollisionInterval& other) {
  into.t0 = std::min(into.t0, other.t0);
  into.t1 = std::max(into.t1, other.t1);
  into.box.extend(other.box);
  for (int p : other.parts) add_part(into.parts, p);
  into.containment = into.containment || other.containment;
  into.possible = into.possible && other.possible;
  into.triangles.insert(into.triangles.end(), other.triangles.begin(), other.triangles.end());
}

}  // namespace reconfig::collision::detail
