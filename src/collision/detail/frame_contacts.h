#pragma once
/// @file
/// What the detector has found of one pair of parts in one frame: its contacts merged into
/// groups (any two that meet in time and space merge, to a fixpoint, which does not depend on
/// the order contacts arrive in), and the test that lets the traversal skip work whose every
/// possible contact would fall inside a group already.

#include <vector>

#include "reconfig/collision/collision_interval.h"
#include "reconfig/collision/triangle_contact.h"

namespace reconfig::collision::detail {

class FrameContacts {
 public:
  /// @param gap  boxes closer than this (on every axis) count as meeting
  /// @param witnesses  whether the groups keep their parts and triangle pairs (pruning needs
  ///        only their extents, which are the same either way)
  explicit FrameContacts(double gap, bool witnesses = true) : gap_(gap), witnesses_(witnesses) {}

  /// Merges a contact of this pair of parts within this frame.
  void add(const TriangleContact& contact);

  /// How far the time range [t0, t1] and the box stick out of the confirmed (not `possible`)
  /// group they stick out of least, relative to their own size: the larger of the time they
  /// extend beyond the group's time range over t1 − t0, and the largest distance, along an
  /// axis, by which a face of the box lies outside the group's box over the box's longest
  /// side. 0 if some confirmed group contains both: then any contact within them merges into
  /// that group and changes nothing. Infinite if there is no confirmed group.
  /// (Relative: work whose box lies mostly outside the groups is the likeliest to hold the
  /// contacts that make their extents. Ordered by absolute distances instead, the traversal
  /// does 15 % more bound tests on the bunny sweep, 38 % more on the gallery.)
  double protrusion(double t0, double t1, const Eigen::AlignedBox3d& box) const;

  const std::vector<CollisionInterval>& groups() const { return groups_; }

 private:
  double gap_;
  bool witnesses_;
  std::vector<CollisionInterval> groups_;
};

}  // namespace reconfig::collision::detail
