#pragma once
/// @file
/// Turning raw narrow-phase contacts into collision intervals a designer can read
/// (reconfigurables §4.1): contacts of one pair of parts whose time extents overlap or touch
/// and whose spatial boxes overlap merge into one conservative interval of that pair.

#include <limits>
#include <vector>

#include "reconfig/collision/collision_interval.h"
#include "reconfig/collision/triangle_contact.h"

namespace reconfig::collision {

/// Merges intervals (the detector's groups of contacts per pair and frame) and containments:
/// any two of the same pair of parts that meet in time and space merge, until none do
/// (without a duration limit the result does not depend on the order in which they merge).
/// Intervals of different pairs never merge, however they overlap: each names one pair.
/// @param max_duration  a merged interval never spans more time than this (default: no limit,
///                      the maximal consolidation the timeline shows; the 3D view uses one
///                      frame so its boxes stay tight). A single contact longer than the limit
///                      stays whole.
/// @return intervals sorted by (t0, parts)
std::vector<CollisionInterval> consolidate(std::vector<CollisionInterval> intervals,
                                           const std::vector<Containment>& containments,
                                           double max_duration = std::numeric_limits<double>::infinity());

/// The same from raw contacts, each first made an interval of its two parts.
std::vector<CollisionInterval> consolidate(const std::vector<TriangleContact>& contacts,
                                           const std::vector<Containment>& containments,
                                           double max_duration = std::numeric_limits<double>::infinity());

/// One contact as an interval of its two parts and its triangle pair.
CollisionInterval contact_interval(const TriangleContact& contact);

}  // namespace reconfig::collision
