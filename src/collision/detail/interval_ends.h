#pragma once
/// @file
/// The exact first and last times of collision intervals. The traversal finds contacts in
/// pieces of a proxy step (1/32 of it) clipped to frames, so an interval's ends are only known
/// to within such a piece; here each end is re-detected over the piece that holds it, again
/// and again (each time 32 times finer), until it is known to within `kEndTolerance` of the
/// transition.

#include <vector>

#include "reconfig/collision/collision_interval.h"
#include "reconfig/collision/spacetime_detector.h"

namespace reconfig::collision::detail {

/// How close a refined end lies to the true one (fraction of the transition).
inline constexpr double kEndTolerance = kIntervalEndTolerance;

/// Refines the ends of every interval the groups consolidate into (`consolidate`), and clips
/// each group to the refined ends of its interval (dropping it if nothing is left). A refined
/// start is the start of the earliest re-detected contact piece, no longer than
/// `kEndTolerance`: no interference of the interval lies before it (every detection of a window
/// is complete), and the piece is one the narrow phase could not clear — so the reported start
/// lies at most `kEndTolerance` before the true one, or before the time where the triangles
/// come within the narrow phase's distance tolerance. Ends alike. The windows re-detected are
/// the groups' spans, so the refined ends depend on the groups alone (an update refines as a
/// detection from scratch does). In conservative mode nothing is refined: its ends must cover
/// the true motion's, which the proxies' re-detection would not. The ends are re-detected in
/// parallel, each on its own. Adds the re-detections' work to `stats` (`end_refinements`).
void refine_interval_ends(const scene::Reconfigurable& scene, const BodyTrees& trees,
                          const std::vector<PartProxy>& proxies, const DetectorOptions& options,
                          std::vector<CollisionInterval>& groups, DetectionStats& stats);

}  // namespace reconfig::collision::detail
