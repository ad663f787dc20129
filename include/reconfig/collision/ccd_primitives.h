#pragma once
/// @file
/// Continuous collision tests for linearly moving primitives (the narrow phase's building
/// blocks): does a moving vertex touch a moving triangle, do two moving segments touch, for
/// some time in [0, 1]?
///
/// Every vertex moves on a straight line: x(t) = x0 + t (x1 − x0). The contact conditions are
///
///   vertex–face  F(t, u, v) = p(t) − [a(t) + u (b(t) − a(t)) + v (c(t) − a(t))] = 0,
///                t ∈ [0, 1], u, v ≥ 0, u + v ≤ 1
///   edge–edge    F(t, u, v) = [a(t) + u (b(t) − a(t))] − [c(t) + v (d(t) − c(t))] = 0,
///                t, u, v ∈ [0, 1]
///
/// Method (inclusion-based bisection, after Wang et al. 2021, "A Large-Scale Benchmark and an
/// Inclusion-Based Algorithm for Continuous Collision Detection"; own implementation): F is
/// affine in each of t, u and v separately, so over a box of (t, u, v) each coordinate of F
/// ranges exactly between its smallest and largest value at the box's 8 corners. Corners are
/// evaluated in double precision under a proven rounding-error bound. A box whose range
/// excludes 0 in some coordinate (by more than the error bound) holds no contact and is
/// dropped; otherwise it is split, the dimension that spreads F most first, earliest time first.
///
/// Guarantees, for finite coordinates of magnitude below 2^1000:
/// - **No false negatives.** If the exact input primitives touch at some t in the range,
///   `hit` is true. Every box containing a contact keeps 0 in its range, so it is never dropped.
/// - **False positives only within the tolerance.** `hit` is true only when some box of the
///   search has an F range of width ≤ `tolerance` in every coordinate containing 0 (up to the
///   error bound e and the separation s), so at one of its times the vertex is within
///   L∞ distance `tolerance + 2e + s` of the triangle (the edges within that of each other);
///   or when a *witness* was found: a point (t, u, v) of the domain where the computed F is
///   within `tolerance` in every coordinate, so the exact F within `tolerance + e` (found by
///   floating-point root finding on the coplanarity cubic and a least-squares (u, v), tried
///   once the first box, the whole domain, is not excluded); or when the work budget
///   `max_boxes` ran out (`budget_exhausted`), which is answered "hit" to stay conservative.
/// - **Earliest contact.** With `earliest` (the default), `toi` is a lower bound on the
///   earliest contact time: no contact happens in [t_min, toi). After the first hit, the
///   boxes still waiting are cut at the current `toi` and halved until each is excluded or as
///   short as the first accepted box (whose start then bounds `toi`): tight to about
///   `tolerance` / (relative speed) when the motion, not the (u, v) extent, decides. After a
///   witness at t*, toi = t* − w, w the time F needs to change by `tolerance`, if the four
///   points are certainly never coplanar before (`coplanarity_cubic.h`; only without a
///   `separation`, which makes near misses count); else the search starts again on
///   [t_min, t* − w], with its direction tests taken at each box's end (the geometry nearest
///   the known contact separates best). A simple crossing is settled without a search.
/// - **Robust "no".** A "no" is certified with a margin: it stays "no" when every vertex
///   position is perturbed by up to `robust_perturbation` of the scale (see below). The
///   triangle-pair narrow phase relies on this to evaluate static tests at rounded positions.
///
/// The error bound is e = 128 ε M with ε = 2^-53 and M the largest absolute input coordinate
/// (plus a denormal guard): coordinates far from the origin get a proportionally larger e.

#include <Eigen/Core>

namespace reconfig::collision {

/// Tuning of one vertex–face or edge–edge query.
struct PrimitiveCcdOptions {
  /// Width (per coordinate, in model units) of F's range below which a box that may hold a
  /// contact is accepted as a hit. Smaller is tighter and slower; must be > 0.
  double tolerance = 1e-6;
  /// Extra margin (L∞, model units) added to every "may the range hold 0" decision: the query
  /// then answers whether the primitives come within `separation` of each other (in the
  /// parametrized sense of F). Used to absorb the error of inputs rounded to double
  /// (`reconfig ccd-queries` passes 4× the largest conversion error for vertex–face, 2× for
  /// edge–edge) and as a minimum separation. ≥ 0.
  double separation = 0;
  /// Time range searched, a sub-range of [0, 1].
  double t_min = 0, t_max = 1;
  /// Work budget: boxes examined before giving up with a conservative hit.
  int max_boxes = 1'000'000;
  /// Keep searching after the first hit for the earliest one (a tight `toi`). Without it the
  /// search stops at the first witness or box accepted, and `toi` is the witness's time or
  /// that box's start (a time with a near-contact, but not a lower bound on the first one).
  bool earliest = true;
};

/// Answer of one vertex–face or edge–edge query.
struct PrimitiveCcdResult {
  bool hit = false;  ///< the primitives may touch in [t_min, t_max] (never false if they do)
  /// When `hit`: a lower bound on the earliest contact time (t_min ≤ toi ≤ first contact) if
  /// `earliest`, else a time with a near-contact (see `earliest`); t_max when there is no hit.
  double toi = 1;
  int boxes = 0;                 ///< boxes examined (work measure)
  bool budget_exhausted = false; ///< `hit` was forced by the `max_boxes` budget
};

/// Relative size of a vertex perturbation that never turns a "no" answer into a contact:
/// each coordinate may move by up to `kRobustPerturbation × M` (M = largest absolute input
/// coordinate), which covers the rounding of x0 + t (x1 − x0) in double precision.
inline constexpr double kRobustPerturbation = 6.0 * 0x1p-53;

/// Whether vertex p touches triangle (a, b, c) for some t in [t_min, t_max]. The triangle may
/// be degenerate (a segment or a point): its point set is what counts.
/// @param p0,a0,b0,c0  positions at t = 0 (3-vectors)
/// @param p1,a1,b1,c1  positions at t = 1
PrimitiveCcdResult vertex_face_ccd(const Eigen::Vector3d& p0, const Eigen::Vector3d& a0, const Eigen::Vector3d& b0,
                                   const Eigen::Vector3d& c0, const Eigen::Vector3d& p1, const Eigen::Vector3d& a1,
                                   const Eigen::Vector3d& b1, const Eigen::Vector3d& c1,
                                   const PrimitiveCcdOptions& options = {});

/// Whether segment (a, b) touches segment (c, d) for some t in [t_min, t_max]. Segments may be
/// degenerate (points).
/// @param a0,b0,c0,d0  positions at t = 0 (3-vectors)
/// @param a1,b1,c1,d1  positions at t = 1
PrimitiveCcdResult edge_edge_ccd(const Eigen::Vector3d& a0, const Eigen::Vector3d& b0, const Eigen::Vector3d& c0,
                                 const Eigen::Vector3d& d0, const Eigen::Vector3d& a1, const Eigen::Vector3d& b1,
                                 const Eigen::Vector3d& c1, const Eigen::Vector3d& d1,
                                 const PrimitiveCcdOptions& options = {});

}  // namespace reconfig::collision
