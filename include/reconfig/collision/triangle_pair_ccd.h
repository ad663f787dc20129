#pragma once
/// @file
/// The narrow phase of the spacetime collision engine: the exact set of times at which two
/// triangles with linearly moving vertices intersect (reconfigurables §5.4: the δt ⊂ ∆t of a
/// candidate pair of spacetime primitives).
///
/// Why it works: the closed triangles' intersection status can only change at a contact
/// event — a vertex of one on the other (6 vertex–face pairs) or an edge of each meeting
/// (9 edge–edge pairs). Between events the triangles either stay apart or intersect through
/// transversal piercings, which survive small perturbations. So the time step is bisected
/// (coarsest pieces first): a piece on which no contact can occur has one status throughout,
/// decided by one exact static test (`geometry::triangles_intersect`) at its middle time —
/// evaluated at rounded vertex positions, which is safe because every "no contact" below is
/// certified robust to that rounding. A test whose two primitives' boxes over the step stay
/// apart is dropped at once; a contact needs its four points coplanar, so a cheap
/// certified bound on that cubic (`coplanarity_cubic.h`) rules out most of the other tests on
/// most pieces; a piece longer than 1/32 of the step where some cubic may vanish strictly
/// inside is halved without running its contact test, shorter pieces (and cubics vanishing
/// at a piece's end) run the contact tests (`ccd_primitives.h`); a piece where a contact may
/// occur
/// is halved until it is shorter than the time tolerance, and then reported whole if it holds
/// an intersection: if the static test says so at one of its ends, else if a contact test
/// still fires (the status is otherwise the ends' throughout).

#include <Eigen/Core>
#include <array>
#include <functional>
#include <vector>

namespace reconfig::collision {

/// A closed time interval [lo, hi] (lo == hi for a single instant).
struct TimeInterval {
  double lo = 0, hi = 0;
};

/// Two triangles over one time step [t0, t1]; vertex k of a triangle moves linearly from
/// `*_start[k]` (at t0) to `*_end[k]` (at t1). Triangles may be degenerate (segments, points).
struct TrianglePairCcdRequest {
  std::array<Eigen::Vector3d, 3> a_start, a_end;  ///< triangle A: 3 vertices at t0 and at t1
  std::array<Eigen::Vector3d, 3> b_start, b_end;  ///< triangle B: 3 vertices at t0 and at t1
  double t0 = 0, t1 = 1;                           ///< the time step (t0 < t1)
  /// Distance tolerance of the contact tests (`PrimitiveCcdOptions::tolerance`, model units).
  double distance_tolerance = 1e-6;
  /// Pieces of the step where a contact may occur are refined down to this fraction of
  /// the step, then reported whole.
  double time_tolerance = 1e-6;
  /// Work budget: pieces examined before the remaining undecided pieces are reported whole.
  int max_pieces = 4096;
  /// Work budget of each contact test (`PrimitiveCcdOptions::max_boxes`).
  int max_boxes = 100'000;
  /// Optional: whether the caller cares about the times of a piece [lo, hi] of the step (in
  /// step parameters, 0 at t0 and 1 at t1), asked of every piece where a contact may occur
  /// before it is tested or halved. A piece it rejects is dropped, with its halves; every
  /// other piece is treated as without it. (The detector rejects the pieces where whatever the
  /// triangles could meet in lies inside a group it has found already.) It must not call
  /// `triangle_pair_ccd` itself.
  std::function<bool(double lo, double hi)> relevant;
  /// Whether pieces reported whole that touch merge into one interval. Off, each is its own
  /// interval, so that what is reported of a time does not depend on what is reported next to
  /// it (the detector's boxes of where triangles meet over an interval would: that of a union
  /// is larger than the union of those of its parts).
  bool merge_pieces = true;
};

/// When the triangles intersect.
struct TrianglePairCcdResult {
  /// Sorted, disjoint closed intervals within [t0, t1] (without `merge_pieces`, touching ones
  /// may share an end) covering every time at which the closed triangles share a point (no
  /// false negatives), except times that lie only in pieces `relevant` rejected. Inflation: a
  /// reported time is either a true intersection time or lies in a piece of at most
  /// `time_tolerance`·(t1 − t0) (or, if the budget ran out, a larger undecided piece)
  /// containing a time at which a vertex and a triangle, or two edges, come within the contact
  /// tests' tolerance (L∞, see `ccd_primitives.h`). Endpoints are rounded outward.
  std::vector<TimeInterval> intervals;
  bool budget_exhausted = false;  ///< some pieces were reported whole because of `max_pieces`
  int pieces = 0;                 ///< pieces of the step examined (work measure)
  int contact_tests = 0;          ///< vertex–face and edge–edge tests run (work measure)

  bool any() const { return !intervals.empty(); }
  /// Whether time t lies in a reported interval.
  bool contains(double t) const;
};

/// The times in [t0, t1] at which the two moving closed triangles intersect, conservatively.
/// Non-finite coordinates give no intersection.
TrianglePairCcdResult triangle_pair_ccd(const TrianglePairCcdRequest& request);

}  // namespace reconfig::collision
