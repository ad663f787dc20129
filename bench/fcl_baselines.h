#pragma once
/// @file
/// FCL 0.7 (Debian libfcl-dev) as the collision benchmark's baseline, asked three ways:
/// discrete `fcl::collide` at given sample times (the engine's proxy times, or the step that
/// makes the engine's promise, `guaranteed_steps.h`), and FCL's continuous collision
/// (conservative advancement over an interpolated motion) per pair of parts over each step,
/// which answers only the time of the first contact in the step. Built only when CMake finds
/// FCL (RECONFIG_HAVE_FCL).
///
/// FCL 0.7's `fcl::continuousCollide` itself cannot be used on meshes as it is: with
/// `CCDC_CONSERVATIVE_ADVANCEMENT` its dispatch table runs a generic version that finds no
/// contact on two unit boxes sliding through each other (RSS) or crashes (OBBRSS), and its
/// `ScrewMotion` puts a box sliding without turning in the wrong place (`CCDC_NAIVE` then
/// reports contact at t = 0.056 instead of 1/3). The baseline calls the mesh–mesh conservative
/// advancement that the dispatch should have reached (`conservativeAdvancementMeshOriented`
/// over RSS trees) with `InterpMotion` (`CCDM_LINEAR`'s motion, about the part's center), which
/// gets 1/3.

#include <fcl/geometry/collision_geometry.h>

#include <memory>
#include <utility>
#include <vector>

#include "reconfig/collision/collision_interval.h"
#include "reconfig/scene/reconfigurable.h"

namespace reconfig::bench {

/// FCL's own bounding volume hierarchy (`BVHModel<OBBRSS>`) of every part, in its body frame.
struct FclParts {
  std::vector<std::shared_ptr<fcl::CollisionGeometryd>> geometry;
};
FclParts fcl_parts(const scene::Reconfigurable& scene);

/// What discrete FCL finds at one time: the intersecting pairs of parts (a < b, sorted), and
/// how many intersecting triangle pairs (one per pair unless every contact was asked for).
struct FclSample {
  std::vector<std::pair<int, int>> pairs;
  long triangle_pairs = 0;
};

/// Discrete FCL at time t of `transition`: a broad phase over the parts' AABBs
/// (DynamicAABBTree), then `fcl::collide` per candidate pair, which stops at the first
/// intersecting triangle pair, or with `all_contacts` finds every one.
FclSample fcl_sample(const scene::Reconfigurable& scene, int transition, const FclParts& parts, double t, bool all_contacts);

/// The first contact FCL's continuous collision finds for parts a < b within step `step`
/// [times[step], times[step + 1]], at time t of the transition.
struct FclFirstContact {
  int a = 0, b = 0;
  int step = 0;
  double t = 0;
};

/// FCL's continuous collision over every step of `times` (sorted, from 0 to 1) for every pair
/// of parts of which one moves: each part's center moves linearly between its poses at the
/// step's ends while the part turns about it at constant angular velocity (`fcl::InterpMotion`),
/// solved by FCL's mesh–mesh conservative advancement over the OBBRSS trees, for the pairs whose swept
/// bounding spheres' boxes meet (a conservative broad phase for that motion). Parallel over the pairs and steps.
struct FclCcdResult {
  std::vector<FclFirstContact> contacts;  ///< sorted by (a, b, step)
  long pair_steps = 0;                    ///< (pair, step)s the broad phase kept: continuousCollide calls
};
FclCcdResult fcl_ccd_first_contacts(const scene::Reconfigurable& scene, int transition, const FclParts& parts,
                                                    const std::vector<double>& times);

/// What FCL's continuous collision tells of the engine's collision intervals.
struct CcdComparison {
  int intervals = 0;         ///< the engine's intervals: its groups merged per pair over time
  int starts_found = 0;      ///< intervals whose start an FCL first contact gives (within the time tolerance)
  int starts_missed = 0;     ///< intervals whose start FCL does not give (mostly: a later interval within a step)
  int intervals_missed = 0;  ///< intervals during which FCL reports no contact at all
  int ends_unreported = 0;   ///< interval ends before the transition's end: FCL never reports an end
  int extra_contacts = 0;    ///< FCL first contacts in no engine interval of the pair (within the time tolerance)
  int pairs = 0;             ///< pairs of parts the engine finds colliding
  int pairs_missed = 0;      ///< … of which FCL finds no contact
  double first_contact_error = 0;  ///< largest |FCL's first contact − the engine's| over those pairs
};

/// Compares FCL's first contacts with the engine's groups (`SpacetimeDetector::groups`).
/// @param time_tolerance  how far apart in time two answers may be and still agree
CcdComparison compare_with_engine(const std::vector<FclFirstContact>& contacts,
                                  const std::vector<collision::CollisionInterval>& engine_groups, double time_tolerance);

/// The engine's groups merged per pair of parts into maximal time intervals (as `t0`, `t1`,
/// `parts` of the result), sorted by (parts, t0).
std::vector<collision::CollisionInterval> time_intervals_per_pair(const std::vector<collision::CollisionInterval>& groups);

}  // namespace reconfig::bench
