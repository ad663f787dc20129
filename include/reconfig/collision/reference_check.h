#pragma once
/// @file
/// The reference collision check: dense time sampling with exact static tests. Slow and
/// obviously correct; it is the oracle the spacetime engine is tested against.

#include <vector>

#include "reconfig/collision/collision_interval.h"
#include "reconfig/common/progress.h"
#include "reconfig/scene/reconfigurable.h"

namespace reconfig::collision {

struct ReferenceCheckRequest {
  /// Time samples per transition, evenly spaced over [0, 1] including both ends (≥ 2).
  int samples = 1000;
  /// Transitions to check (indices); empty means all.
  std::vector<int> transitions;
  /// Also report a part lying entirely inside another (no surface crossing).
  bool detect_containment = true;
  /// The contact tolerance δ (0: the design's default, `contact_tolerance.h`): triangle pairs
  /// that only touch within δ (`triangle_touching.h`) are not a collision...
  double contact = 0;
  /// ...unless touching collides.
  bool touching_collides = false;
  /// Also report, as clearance intervals, the samples where two parts that do not collide come
  /// closer than this (some triangle pair's distance, `triangle_distance`; 0: no clearance check).
  double clearance = 0;
  ProgressCallback progress;  ///< fraction of samples done over all transitions
};

/// What happened at one sample of one transition, per colliding pair of parts.
struct SampleContact {
  int sample = 0;
  int part_a = 0, part_b = 0;  ///< part_a < part_b
  Eigen::AlignedBox3d box;      ///< box of the intersection at that instant
  bool containment = false;
  int triangle_pairs = 0;       ///< number of intersecting triangle pairs (0 for containment)
  /// Not colliding, but closer than the clearance (`box`: that of the triangles that are).
  bool clearance = false;
};

struct ReferenceCheckResult {
  std::vector<TransitionCollisions> transitions;  ///< one per checked transition, in order
  /// Per transition (same order), every colliding (sample, pair): the raw oracle data.
  std::vector<std::vector<SampleContact>> contacts;
  int samples = 0;
  /// How far a sampled end may lie from the true one: an interval [t_i, t_j] of samples means
  /// the true one starts in (t_{i−1}, t_i] and ends in [t_j, t_{j+1}) — one sample spacing,
  /// 1 / (samples − 1) (an interval shorter than that may be missed altogether).
  double time_error = 0;
  double contact = 0;  ///< the contact tolerance δ used
  bool cancelled = false;

  /// Whether any transition has a collision (or clearance) interval.
  bool any_collision() const;
};

/// For every requested transition, poses every part at each sample time, finds intersecting
/// triangle pairs of every pair of parts with a static BVH and the exact triangle test (those
/// that only touch within δ left out unless touching collides), and
/// (optionally) a part entirely inside another. Consecutive colliding samples of the same pair
/// of parts merge into one collision interval whose box bounds the intersections seen.
/// Parallel over samples; the result is deterministic.
/// @param scene  a validated reconfigurable
ReferenceCheckResult reference_check(const scene::Reconfigurable& scene, const ReferenceCheckRequest& request = {});

/// The time of sample i of n: i / (n − 1).
inline double sample_time(int i, int samples) { return static_cast<double>(i) / (samples - 1); }

}  // namespace reconfig::collision
