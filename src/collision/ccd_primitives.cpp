#include "reconfig/collision/ccd_primitives.h"

#include "collision/detail/determinant.h"
#include "reconfig/collision/coplanarity_cubic.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

namespace reconfig::collision {
namespace {

using detail::det3;

/// Four moving points, as coordinates at t = 0 and t = 1 (x[k][axis], k = vertex).
struct MovingQuad {
  double x0[4][3];
  double x1[4][3];
};

/// A box of the (t, u, v) search domain and how often each side has been halved.
struct Box {
  double lo[3], hi[3];
  unsigned char depth[3];
};

/// Halving stops at this depth per dimension: u, v stay multiples of 2^-52, so the simplex
/// test u_lo + v_lo > 1 is exact.
constexpr int kMaxDepth = 52;
/// Deepest possible search: every dimension at its maximum depth. The depth-first stack holds
/// at most one pending sibling per level.
constexpr int kStackSize = 3 * kMaxDepth + 4;

enum class Kind { kVertexFace, kEdgeEdge };

/// F(t, u, v) = d(t) + u e1(t) + v e2(t): for vertex–face d = p − a, e1 = −(b − a), e2 = −(c − a);
/// for edge–edge d = a − c, e1 = b − a, e2 = −(d − c). Negations are exact, so both kinds share
/// one rounding-error analysis (see `error_bound`).
template <Kind kind>
inline void terms_at(const MovingQuad& q, double t, double d[3], double e1[3], double e2[3]) {
  for (int i = 0; i < 3; ++i) {
    double x[4];
    for (int k = 0; k < 4; ++k) x[k] = q.x0[k][i] + t * (q.x1[k][i] - q.x0[k][i]);
    if constexpr (kind == Kind::kVertexFace) {
      d[i] = x[0] - x[1];
      e1[i] = x[1] - x[2];
      e2[i] = x[1] - x[3];
    } else {
      d[i] = x[0] - x[2];
      e1[i] = x[1] - x[0];
      e2[i] = x[2] - x[3];
    }
  }
}

/// Bound on |computed F − exact F| at any (t, u, v) in [0,1]^3, plus the robustness margin.
///
/// With M the largest |coordinate| and ε = 2^-53 (first-order terms; the constant absorbs the
/// rest): x0 + t(x1 − x0) is within 6εM of x(t) (difference 2εM, product 4εM, sum +εM·…);
/// a difference of two such is within 14εM (|·| ≤ 2M); u·e within 16εM; d + u e1 (|·| ≤ 4M)
/// within 34εM; + v e2 (|·| ≤ 6M) within 56εM. Robustness: moving every vertex by ≤ 6εM moves
/// F by ≤ 4·6εM = 24εM (|1 − u − v| + u + v + 1 ≤ 4). 56 + 24 = 80 ≤ 128. Denormals: each
/// operation adds at most 2^-1075 absolutely; the guard covers a few hundred.
inline double error_bound(const MovingQuad& q) {
  double m = 0;
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 3; ++i) m = std::max({m, std::abs(q.x0[k][i]), std::abs(q.x1[k][i])});
  return 128.0 * 0x1p-53 * m + 0x1p-1000;
}

inline bool finite(const MovingQuad& q) {
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 3; ++i)
      if (!std::isfinite(q.x0[k][i]) || !std::isfinite(q.x1[k][i]) || std::abs(q.x0[k][i]) > 0x1p1000 ||
          std::abs(q.x1[k][i]) > 0x1p1000)
        return false;
  return true;
}

inline void cross(const double a[3], const double b[3], double r[3]) {
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}

/// Whether the 8 corner values (each within `margin` of the exact F per coordinate) lie
/// strictly on one side of a plane through 0. F is multilinear, so its values over the box are
/// convex combinations of the corner values: one separating direction excludes the box.
///
/// The axis directions (tested by the caller) fail when the corners hug a slanted line or plane
/// near 0 — near-collinear edges, a vertex sliding in the face's plane, degenerate triangles —
/// and subdividing then costs O(1 / distance) boxes. So a few directions computed from the
/// geometry at the box's start are tried too: F at the box's middle (u, v), the normal e1 × e2,
/// and the components of F perpendicular to e1 and to e2. Any direction is valid; only the dot
/// products need error bounds: |n·F − fl(n·F̃)| ≤ |n|₁ margin + 4ε Σ|n_i F̃_i| (doubled).
inline bool separated_along_directions(const double f[8][3], const double d[3], const double e1[3],
                                       const double e2[3], const Box& box, double margin) {
  const double um = 0.5 * (box.lo[1] + box.hi[1]), vm = 0.5 * (box.lo[2] + box.hi[2]);
  double n[4][3];
  for (int i = 0; i < 3; ++i) n[0][i] = d[i] + um * e1[i] + vm * e2[i];
  cross(e1, e2, n[1]);
  double tmp[3];
  cross(n[0], e1, tmp);
  cross(e1, tmp, n[2]);
  cross(n[0], e2, tmp);
  cross(e2, tmp, n[3]);
  for (const auto& dir : n) {
    const double norm1 = std::abs(dir[0]) + std::abs(dir[1]) + std::abs(dir[2]);
    if (!(norm1 > 0) || !std::isfinite(norm1)) continue;
    bool positive = true, negative = true;
    for (int c = 0; c < 8 && (positive || negative); ++c) {
      const double dot = dir[0] * f[c][0] + dir[1] * f[c][1] + dir[2] * f[c][2];
      const double size = std::abs(dir[0] * f[c][0]) + std::abs(dir[1] * f[c][1]) + std::abs(dir[2] * f[c][2]);
      const double bound = norm1 * margin + 8 * 0x1p-53 * size + 0x1p-1000;
      positive = positive && dot > bound;
      negative = negative && dot < -bound;
    }
    if (positive || negative) return true;
  }
  return false;
}

/// Boxes the search examines before it looks for a witness (below): the first box, the whole
/// domain, already excludes far misses, and a contact would otherwise cost a descent of
/// dozens of boxes to the tolerance.
constexpr int kWitnessAfterBoxes = 1;

double cubic_at(const double c[4], double t) { return ((c[3] * t + c[2]) * t + c[1]) * t + c[0]; }

/// A root of cubic c in [lo, hi], where c(lo) and c(hi) differ in sign (or one is 0):
/// Newton's method kept inside the shrinking bracket, bisection when it strays.
double bracketed_root(const double c[4], double lo, double hi) {
  double f_lo = cubic_at(c, lo);
  if (f_lo == 0) return lo;
  double t = 0.5 * (lo + hi);
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double f = cubic_at(c, t);
    if (f == 0) return t;
    if ((f < 0) == (f_lo < 0)) lo = t, f_lo = f;
    else hi = t;
    const double slope = (3 * c[3] * t + 2 * c[2]) * t + c[1];
    double next = t - f / slope;
    if (!(lo < next && next < hi)) next = 0.5 * (lo + hi);
    if (next == t || hi - lo <= 0x1p-52 * std::max(1.0, std::abs(t))) return next;
    t = next;
  }
  return t;
}

/// Candidate contact times in [lo, hi]: the roots of the coplanarity cubic c (where it
/// changes sign between its turning points), then the turning points themselves (tangent
/// roots), then the ends. Floating point throughout: candidates are verified by the caller.
int contact_time_candidates(const double c[4], double lo, double hi, double out[7]) {
  double breaks[4] = {lo, 0, 0, hi};
  int count = 1;
  // Turning points: roots of 3 c3 t² + 2 c2 t + c1.
  const double qa = 3 * c[3], qb = 2 * c[2], qc = c[1];
  double turning[2];
  int turnings = 0;
  if (qa != 0) {
    const double disc = qb * qb - 4 * qa * qc;
    if (disc >= 0) {
      const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
      if (q != 0) turning[turnings++] = q / qa, turning[turnings++] = qc / q;
      else turning[turnings++] = 0;
    }
  } else if (qb != 0) {
    turning[turnings++] = -qc / qb;
  }
  if (turnings == 2 && turning[0] > turning[1]) std::swap(turning[0], turning[1]);
  for (int k = 0; k < turnings; ++k)
    if (lo < turning[k] && turning[k] < hi) breaks[count++] = turning[k];
  breaks[count++] = hi;
  int found = 0;
  for (int k = 0; k + 1 < count; ++k) {
    const double a = cubic_at(c, breaks[k]), b = cubic_at(c, breaks[k + 1]);
    if ((a <= 0 && b >= 0) || (a >= 0 && b <= 0)) out[found++] = bracketed_root(c, breaks[k], breaks[k + 1]);
  }
  for (int k = 1; k + 1 < count; ++k) out[found++] = breaks[k];
  out[found++] = lo;
  out[found++] = hi;
  return found;
}

/// Looks for a witness of a contact: a point (t, u, v) of the domain at which the computed F
/// is within the tolerance in every coordinate. Like an accepted box of the search, it proves
/// that at time t the exact primitives come within L∞ distance tolerance + e (the error bound)
/// of each other. Candidates: the times where the four points are coplanar (a root of the
/// cubic det(d, e1, e2)), where (u, v) minimize |F| and are then clamped into the domain.
/// Returns the witness's time, or a negative number if none of the candidates is one.
template <Kind kind>
double contact_witness(const MovingQuad& q, const PrimitiveCcdOptions& options) {
  double d0[3], e10[3], e20[3], d1[3], e11[3], e21[3];
  terms_at<kind>(q, 0, d0, e10, e20);
  terms_at<kind>(q, 1, d1, e11, e21);
  double dd[3], de1[3], de2[3];
  for (int i = 0; i < 3; ++i) dd[i] = d1[i] - d0[i], de1[i] = e11[i] - e10[i], de2[i] = e21[i] - e20[i];
  const double cubic[4] = {det3(d0, e10, e20), det3(dd, e10, e20) + det3(d0, de1, e20) + det3(d0, e10, de2),
                           det3(d0, de1, de2) + det3(dd, e10, de2) + det3(dd, de1, e20), det3(dd, de1, de2)};
  double times[7];
  const int candidates = contact_time_candidates(cubic, options.t_min, options.t_max, times);
  for (int k = 0; k < candidates; ++k) {
    const double t = std::clamp(times[k], options.t_min, options.t_max);
    double d[3], e1[3], e2[3];
    terms_at<kind>(q, t, d, e1, e2);
    // Least squares for u e1 + v e2 = −d.
    double g11 = 0, g12 = 0, g22 = 0, r1 = 0, r2 = 0;
    for (int i = 0; i < 3; ++i) {
      g11 += e1[i] * e1[i], g12 += e1[i] * e2[i], g22 += e2[i] * e2[i];
      r1 -= d[i] * e1[i], r2 -= d[i] * e2[i];
    }
    const double det = g11 * g22 - g12 * g12;
    if (!(det > 1e-24 * g11 * g22)) continue;  // (near) parallel: left to the search
    double u = std::max(0.0, (r1 * g22 - r2 * g12) / det), v = std::max(0.0, (g11 * r2 - g12 * r1) / det);
    if constexpr (kind == Kind::kVertexFace) {
      // u + v may exceed 1 by a rounding, moving the point off the face by ≤ 2^-52 of an edge,
      // well within the error bound.
      if (u + v > 1) u /= u + v, v = 1 - u;
    } else {
      u = std::min(u, 1.0), v = std::min(v, 1.0);
    }
    bool near = true;
    for (int i = 0; i < 3 && near; ++i) near = std::abs(d[i] + u * e1[i] + v * e2[i]) <= options.tolerance;
    if (near) return t;
  }
  return -1;
}

/// Whether the query's four points are certainly never coplanar during [lo, hi] (no contact
/// of any kind can happen then; `coplanarity_cubic.h`, whose verdicts are robust to the same
/// perturbation as a "no" of the search).
bool never_coplanar(const MovingQuad& q, double lo, double hi) {
  MovingPoints points;
  for (int k = 0; k < 4; ++k) {
    points.start[k] = Eigen::Vector3d(q.x0[k][0], q.x0[k][1], q.x0[k][2]);
    points.end[k] = Eigen::Vector3d(q.x1[k][0], q.x1[k][1], q.x1[k][2]);
  }
  return CoplanarityCubic(points, lo, hi).classify() == Coplanarity::kNever;
}

/// The time F takes to change by the tolerance at most: F(t, u, v) moves by at most
/// |Δd| + |Δe1| + |Δe2| (per coordinate, Δ over the whole step) per unit of time.
template <Kind kind>
double witness_refine_width(const MovingQuad& q, const PrimitiveCcdOptions& options) {
  double d0[3], e10[3], e20[3], d1[3], e11[3], e21[3];
  terms_at<kind>(q, 0, d0, e10, e20);
  terms_at<kind>(q, 1, d1, e11, e21);
  double speed = 0;
  for (int i = 0; i < 3; ++i)
    speed = std::max(speed, std::abs(d1[i] - d0[i]) + std::abs(e11[i] - e10[i]) + std::abs(e21[i] - e20[i]));
  const double range = options.t_max - options.t_min;
  return speed * range > options.tolerance ? options.tolerance / speed : range;
}

template <Kind kind>
PrimitiveCcdResult solve(const MovingQuad& q, const PrimitiveCcdOptions& options) {
  assert(options.tolerance > 0 && options.separation >= 0);
  assert(0 <= options.t_min && options.t_min <= options.t_max && options.t_max <= 1);
  PrimitiveCcdResult result;
  result.toi = options.t_max;
  if (!finite(q)) return result;  // like the static test: non-finite geometry touches nothing

  const double margin = error_bound(q) + options.separation;
  const double tolerance = options.tolerance;

  std::array<Box, kStackSize> stack;
  int size = 0;
  stack[size++] = Box{{options.t_min, 0, 0}, {options.t_max, 1, 1}, {0, 0, 0}};

  double refine_width = 0;  // t-width of the first box accepted (or of a witness)
  while (size > 0) {
    Box box = stack[--size];
    if (kind == Kind::kVertexFace && box.lo[1] + box.lo[2] > 1) continue;  // outside the simplex
    if (result.boxes == kWitnessAfterBoxes && !result.hit) {
      // The whole domain is undecided: a contact is likely, and a witness proves one. It ends
      // a "whether" query. For an "earliest" one, what remains is the time before it, less the
      // time F takes to change by the tolerance (also the refinement's width, as after an
      // accepted box): if that is free of contacts, its end bounds the first contact. Usually
      // the four points are never coplanar then, which settles it (unless a separation makes
      // near misses count too); else the search starts again on it.
      const double witness = contact_witness<kind>(q, options);
      if (witness >= 0) {
        result.hit = true;
        result.toi = witness;
        if (!options.earliest) return result;
        refine_width = witness_refine_width<kind>(q, options);
        result.toi = std::max(options.t_min, witness - refine_width);
        size = 0;
        const bool before = result.toi > options.t_min;
        if (before && !(options.separation == 0 && never_coplanar(q, options.t_min, result.toi)))
          stack[size++] = Box{{options.t_min, 0, 0}, {result.toi, 1, 1}, {0, 0, 0}};
        continue;
      }
    }
    if (result.hit) {  // looking for an earlier contact: only [t_lo, toi] matters
      if (box.lo[0] >= result.toi) continue;
      box.hi[0] = std::min(box.hi[0], result.toi);
    }
    if (++result.boxes > options.max_boxes) {
      result.hit = true;
      result.budget_exhausted = true;
      double toi = std::min(result.toi, box.lo[0]);
      for (int k = 0; k < size; ++k) toi = std::min(toi, stack[k].lo[0]);
      result.toi = toi;
      return result;
    }

    // F at the 8 corners: index c = 4·(t hi) + 2·(u hi) + (v hi).
    double f[8][3];
    // The terms at both ends of the box (index: t hi); one end's are kept for the direction
    // tests: its start, or its end when looking for contacts before a known one (the geometry
    // near that contact separates best).
    double d[2][3], e1[2][3], e2[2][3];
    for (int ti = 0; ti < 2; ++ti) {
      terms_at<kind>(q, ti ? box.hi[0] : box.lo[0], d[ti], e1[ti], e2[ti]);
      for (int ui = 0; ui < 2; ++ui) {
        const double u = ui ? box.hi[1] : box.lo[1];
        for (int vi = 0; vi < 2; ++vi) {
          const double v = vi ? box.hi[2] : box.lo[2];
          double* fc = f[4 * ti + 2 * ui + vi];
          for (int i = 0; i < 3; ++i) fc[i] = d[ti][i] + u * e1[ti][i] + v * e2[ti][i];
        }
      }
    }
    const int direction_end = result.hit ? 1 : 0;

    bool excluded = false;
    bool small = true;
    for (int i = 0; i < 3 && !excluded; ++i) {
      double lo = f[0][i], hi = f[0][i];
      for (int c = 1; c < 8; ++c) {
        lo = std::min(lo, f[c][i]);
        hi = std::max(hi, f[c][i]);
      }
      if (lo > margin || hi < -margin) excluded = true;
      if (hi - lo > tolerance) small = false;
    }
    if (excluded || separated_along_directions(f, d[direction_end], e1[direction_end], e2[direction_end], box, margin))
      continue;

    int split = -1;
    // Refining the first contact time: a box that cannot be excluded and is as short as the
    // first accepted box bounds it.
    if (result.hit && (box.hi[0] - box.lo[0] <= refine_width || box.depth[0] >= kMaxDepth)) {
      result.toi = box.lo[0];
      continue;
    }
    // Which dimension spreads F the most (change between opposite faces of the box).
    double spread[3] = {0, 0, 0};
    for (int c = 0; c < 8; ++c)
      for (int dim = 0; dim < 3; ++dim) {
        const int bit = 4 >> dim;  // t: 4, u: 2, v: 1
        if (c & bit) continue;
        for (int i = 0; i < 3; ++i) spread[dim] = std::max(spread[dim], std::abs(f[c | bit][i] - f[c][i]));
      }
    double best = -1;
    for (int dim = 0; dim < 3; ++dim)
      if (box.depth[dim] < kMaxDepth && spread[dim] > best) {
        best = spread[dim];
        split = dim;
      }
    if (small || split < 0) {  // a contact within the tolerance, or no resolution left
      if (!result.hit) refine_width = box.hi[0] - box.lo[0];
      result.hit = true;
      result.toi = std::min(result.toi, box.lo[0]);
      if (!options.earliest) return result;
      continue;  // look for earlier contacts in the boxes still waiting
    }

    const double mid = 0.5 * (box.lo[split] + box.hi[split]);
    Box first = box, second = box;
    first.hi[split] = mid;
    second.lo[split] = mid;
    ++first.depth[split];
    ++second.depth[split];
    // Depth first, earlier times first: the later half waits on the stack.
    stack[size++] = second;
    stack[size++] = first;
  }
  return result;
}

inline void set(MovingQuad& q, int k, const Eigen::Vector3d& x0, const Eigen::Vector3d& x1) {
  for (int i = 0; i < 3; ++i) {
    q.x0[k][i] = x0[i];
    q.x1[k][i] = x1[i];
  }
}

}  // namespace

PrimitiveCcdResult vertex_face_ccd(const Eigen::Vector3d& p0, const Eigen::Vector3d& a0, const Eigen::Vector3d& b0,
                                   const Eigen::Vector3d& c0, const Eigen::Vector3d& p1, const Eigen::Vector3d& a1,
                                   const Eigen::Vector3d& b1, const Eigen::Vector3d& c1,
                                   const PrimitiveCcdOptions& options) {
  MovingQuad q;
  set(q, 0, p0, p1);
  set(q, 1, a0, a1);
  set(q, 2, b0, b1);
  set(q, 3, c0, c1);
  return solve<Kind::kVertexFace>(q, options);
}

PrimitiveCcdResult edge_edge_ccd(const Eigen::Vector3d& a0, const Eigen::Vector3d& b0, const Eigen::Vector3d& c0,
                                 const Eigen::Vector3d& d0, const Eigen::Vector3d& a1, const Eigen::Vector3d& b1,
                                 const Eigen::Vector3d& c1, const Eigen::Vector3d& d1,
                                 const PrimitiveCcdOptions& options) {
  MovingQuad q;
  set(q, 0, a0, a1);
  set(q, 1, b0, b1);
  set(q, 2, c0, c1);
  set(q, 3, d0, d1);
  return solve<Kind::kEdgeEdge>(q, options);
}

}  // namespace reconfig::collision
