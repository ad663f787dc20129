#pragma once
/// @file
/// Clearance of two triangles of two parts: the distance between them, and the times of a
/// proxy step at which two linearly moving triangles come closer than a clearance C — the
/// narrow phase of the clearance check (`DetectorOptions::clearance`); its static form, the
/// distance of two triangles, is `geometry/triangle_closest_points.h`.
///
/// Over a piece [lo, hi] of the step the distance d(s) changes at most L·|s − s'| between two
/// times, where L is the sum of the largest vertex displacements of the two triangles over the
/// step (every point of a triangle moves by a convex combination of its vertices' moves). So
/// with d at the piece's middle: d + L·(hi − lo)/2 < C certifies the whole piece closer than C,
/// and d − L·(hi − lo)/2 ≥ C, or a fixed direction u along which the triangles stay apart by at
/// least C at both ends of the piece (their gap along u is concave in time), certifies it
/// clear. Undecided pieces are halved down to the time tolerance, then reported whole: no time
/// closer than C is missed.

#include <functional>
#include <vector>

#include "reconfig/collision/triangle_pair_ccd.h"
#include "reconfig/collision/triangle_touching.h"
#include "reconfig/geometry/triangle_closest_points.h"

namespace reconfig::collision {

/// Two triangles over one proxy step (step parameter 0 at its start, 1 at its end).
struct TriangleClearanceRequest {
  TriangleCorners a_start, a_end, b_start, b_end;
  double clearance = 0;  ///< C > 0, in scene units
  /// How far a computed distance or gap may be off by rounding (scene units): certificates keep
  /// this margin.
  double rounding = 0;
  /// Undecided pieces are halved down to this fraction of the step, then reported whole.
  double time_tolerance = 1.0 / 32;
  /// Optional, as `TrianglePairCcdRequest::relevant`: a piece it rejects is dropped.
  std::function<bool(double lo, double hi)> relevant;
};

struct TriangleClearanceResult {
  /// Sorted pieces of the step (dyadic, touching ones may share an end) covering every time at
  /// which the triangles are closer than C, except in pieces `relevant` rejected; each is
  /// certified closer than C throughout, or at most `time_tolerance` long.
  std::vector<TimeInterval> intervals;
  int pieces = 0;  ///< pieces examined (work measure)
  bool any() const { return !intervals.empty(); }
};

/// When the moving triangles come closer than the clearance.
TriangleClearanceResult triangles_closer_than(const TriangleClearanceRequest& request);

}  // namespace reconfig::collision
