#include "reconfig/collision/ccd_primitives.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

namespace reconfig::collision {
namespace {

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

  double refine_width = 0;  // t-width of the first box accepted
  while (size > 0) {
    Box box = stack[--size];
    if (kind == Kind::kVertexFace && box.lo[1] + box.lo[2] > 1) continue;  // outside the simplex
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
    double d0[3], e10[3], e20[3];  // terms at the box's start time, kept for the direction tests
    for (int ti = 0; ti < 2; ++ti) {
      double d[3], e1[3], e2[3];
      terms_at<kind>(q, ti ? box.hi[0] : box.lo[0], d, e1, e2);
      if (ti == 0)
        for (int i = 0; i < 3; ++i) d0[i] = d[i], e10[i] = e1[i], e20[i] = e2[i];
      for (int ui = 0; ui < 2; ++ui) {
        const double u = ui ? box.hi[1] : box.lo[1];
        for (int vi = 0; vi < 2; ++vi) {
          const double v = vi ? box.hi[2] : box.lo[2];
          double* fc = f[4 * ti + 2 * ui + vi];
          for (int i = 0; i < 3; ++i) fc[i] = d[i] + u * e1[i] + v * e2[i];
        }
      }
    }

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
    if (excluded || separated_along_directions(f, d0, e10, e20, box, margin)) continue;

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
