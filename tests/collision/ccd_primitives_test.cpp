// Vertex–face and edge–edge continuous tests: constructed cases with exactly known contact
// times (checked in exact rational arithmetic), degenerate and parallel motions, and
// randomized oracle tests (dense exact sampling on integer grids; separated configurations).

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <random>

#include "reconfig/collision/ccd_primitives.h"
#include "reconfig/geometry/triangle_intersection.h"
#include "exact_rational.h"

namespace reconfig::collision {
namespace {

using Eigen::Vector3d;
using geometry::triangles_intersect;

// ---- exact helpers -------------------------------------------------------------------------

using exact::lerp_exact;
using exact::orient_exact;
using exact::Q3;

/// Whether p lies in the closed non-degenerate triangle (a, b, c), exactly (p in its plane).
bool point_in_triangle_exact(const Q3& p, const Q3& a, const Q3& b, const Q3& c) {
  if (orient_exact(a, b, c, p) != 0) return false;
  // Signed areas against the normal n = (b − a) × (c − a).
  auto sub = [](const Q3& x, const Q3& y) { return Q3{x[0] - y[0], x[1] - y[1], x[2] - y[2]}; };
  auto cross = [](const Q3& x, const Q3& y) {
    return Q3{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
  };
  auto dot = [](const Q3& x, const Q3& y) { return mpq_class(x[0] * y[0] + x[1] * y[1] + x[2] * y[2]); };
  const Q3 n = cross(sub(b, a), sub(c, a));
  return dot(n, cross(sub(b, a), sub(p, a))) >= 0 && dot(n, cross(sub(c, b), sub(p, b))) >= 0 &&
         dot(n, cross(sub(a, c), sub(p, c))) >= 0;
}

// ---- vertex–face: constructed --------------------------------------------------------------

struct Vf {
  Vector3d p0, a0, b0, c0, p1, a1, b1, c1;
  PrimitiveCcdResult run(const PrimitiveCcdOptions& options = {}) const {
    return vertex_face_ccd(p0, a0, b0, c0, p1, a1, b1, c1, options);
  }
};

Vf still_triangle(const Vector3d& p0, const Vector3d& p1) {
  const Vector3d a(0, 0, 0), b(3, 0, 0), c(0, 3, 0);
  return {p0, a, b, c, p1, a, b, c};
}

TEST(VertexFaceCcd, VertexThroughTheFaceAtOneThird) {
  const Vf q = still_triangle({1, 1, 1}, {1, 1, -2});  // z = 1 − 3t
  const PrimitiveCcdResult r = q.run();
  ASSERT_TRUE(r.hit);
  EXPECT_LE(r.toi, 1.0 / 3.0);
  EXPECT_GT(r.toi, 1.0 / 3.0 - 1e-6);
  // The construction: exactly on the face at t = 1/3, exactly off it just before and after.
  const mpq_class third(1, 3);
  EXPECT_TRUE(point_in_triangle_exact(lerp_exact(q.p0, q.p1, third), lerp_exact(q.a0, q.a1, third),
                                      lerp_exact(q.b0, q.b1, third), lerp_exact(q.c0, q.c1, third)));
  EXPECT_NE(orient_exact(lerp_exact(q.a0, q.a1, third), lerp_exact(q.b0, q.b1, third), lerp_exact(q.c0, q.c1, third),
                         lerp_exact(q.p0, q.p1, mpq_class(third - mpq_class(1, 1000000)))),
            0);
}

TEST(VertexFaceCcd, VertexPassingBesideTheFaceMisses) {
  EXPECT_FALSE(still_triangle({2.5, 2.5, 1}, {2.5, 2.5, -2}).run().hit);   // u + v = 5/3
  EXPECT_FALSE(still_triangle({-1e-3, 1, 1}, {-1e-3, 1, -1}).run().hit);   // 1e-3 outside edge ca
  EXPECT_FALSE(still_triangle({1, 1, 1}, {1, 1, 1e-4}).run().hit);         // stops above the face
  EXPECT_FALSE(still_triangle({1, 1, 1e-4}, {5, 5, 1e-4}).run().hit);      // parallel, above
}

TEST(VertexFaceCcd, GrazingTheEdgeAtOneInstantHits) {
  // Crosses the plane at t = 1/2 exactly on edge bc (x + y = 3).
  const Vf q = still_triangle({1.5, 1.5, 1}, {1.5, 1.5, -1});
  const PrimitiveCcdResult r = q.run();
  ASSERT_TRUE(r.hit);
  EXPECT_LE(r.toi, 0.5);
  const mpq_class half(1, 2);
  EXPECT_TRUE(point_in_triangle_exact(lerp_exact(q.p0, q.p1, half), lerp_exact(q.a0, q.a1, half),
                                      lerp_exact(q.b0, q.b1, half), lerp_exact(q.c0, q.c1, half)));
  // Grazing a corner, and touching the plane at one instant from above (a tangent path
  // is impossible for a line, so: the vertex comes down onto the face at t = 1 only).
  EXPECT_TRUE(still_triangle({3, 0, 1}, {3, 0, -1}).run().hit);
  const PrimitiveCcdResult end = still_triangle({1, 1, 1}, {1, 1, 0}).run();
  EXPECT_TRUE(end.hit);
  EXPECT_GT(end.toi, 1 - 1e-5);
}

TEST(VertexFaceCcd, TouchingAtTheStartHitsAtTimeZero) {
  const PrimitiveCcdResult r = still_triangle({1, 1, 0}, {1, 1, 5}).run();
  ASSERT_TRUE(r.hit);
  EXPECT_EQ(r.toi, 0.0);
}

TEST(VertexFaceCcd, CoplanarMotion) {
  // In the plane of the face: entering it through edge ca, and passing by it.
  EXPECT_TRUE(still_triangle({-2, 1, 0}, {2, 1, 0}).run().hit);
  EXPECT_FALSE(still_triangle({-2, 4, 0}, {2, 4, 0}).run().hit);
  // The whole configuration moving together (parallel motion), vertex on the face throughout.
  const Vector3d v(7, -3, 2);
  const Vf along{{1, 1, 0}, {0, 0, 0}, {3, 0, 0}, {0, 3, 0}, Vector3d(1, 1, 0) + v, v, Vector3d(3, 0, 0) + v,
                 Vector3d(0, 3, 0) + v};
  EXPECT_TRUE(along.run().hit);
  Vf above = along;
  above.p0.z() += 1e-3;
  above.p1.z() += 1e-3;
  EXPECT_FALSE(above.run().hit);
}

TEST(VertexFaceCcd, ZeroAreaTriangles) {
  // A triangle collapsed to a segment from (0,0,0) to (2,0,0) (c on it), and to a point.
  const Vector3d a(0, 0, 0), b(2, 0, 0), c(1, 0, 0), o(0, 0, 0);
  EXPECT_TRUE(vertex_face_ccd({1, 1, 0}, a, b, c, {1, -1, 0}, a, b, c).hit);
  EXPECT_FALSE(vertex_face_ccd({3, 1, 0}, a, b, c, {3, -1, 0}, a, b, c).hit);
  EXPECT_FALSE(vertex_face_ccd({1, 1, 1e-3}, a, b, c, {1, -1, 1e-3}, a, b, c).hit);
  EXPECT_TRUE(vertex_face_ccd({-1, -1, -1}, o, o, o, {1, 1, 1}, o, o, o).hit);
  EXPECT_FALSE(vertex_face_ccd({-1, -1, -1}, o, o, o, {1, 1, 1.01}, o, o, o).hit);
  // A triangle that collapses during the motion (c passes through segment ab at t = 1/2),
  // its plane y = z; the vertex is in that plane only at t = 1/2, on the collapsed triangle.
  EXPECT_TRUE(vertex_face_ccd({1, 1, -1}, a, b, {1, 1, 1}, {1, -1, 1}, a, b, {1, -1, -1}).hit);
  EXPECT_FALSE(vertex_face_ccd({3, 1, -1}, a, b, {1, 1, 1}, {3, -1, 1}, a, b, {1, -1, -1}).hit);
}

TEST(VertexFaceCcd, BothMoveAndTheTimeRangeIsRespected) {
  // Triangle rises (z = 2t), vertex falls (z = 1 − t): they meet at t = 1/3.
  const Vf q{{1, 1, 1}, {0, 0, 0}, {3, 0, 0}, {0, 3, 0}, {1, 1, 0}, {0, 0, 2}, {3, 0, 2}, {0, 3, 2}};
  const PrimitiveCcdResult all = q.run();
  ASSERT_TRUE(all.hit);
  EXPECT_LE(all.toi, 1.0 / 3);
  PrimitiveCcdOptions late;
  late.t_min = 0.34;
  EXPECT_FALSE(q.run(late).hit);
  PrimitiveCcdOptions early;
  early.t_max = 0.33;
  EXPECT_FALSE(q.run(early).hit);
  PrimitiveCcdOptions around;
  around.t_min = 0.3;
  around.t_max = 0.4;
  const PrimitiveCcdResult r = q.run(around);
  ASSERT_TRUE(r.hit);
  EXPECT_GE(r.toi, 0.3);
  EXPECT_LE(r.toi, 1.0 / 3);
}

TEST(VertexFaceCcd, SeparationWidensTheContact) {
  const Vf q = still_triangle({1, 1, 1}, {1, 1, 1e-3});  // stops 1e-3 above the face
  EXPECT_FALSE(q.run().hit);
  PrimitiveCcdOptions options;
  options.separation = 2e-3;
  EXPECT_TRUE(q.run(options).hit);
}

TEST(VertexFaceCcd, NonFiniteInputTouchesNothing) {
  Vf q = still_triangle({1, 1, 1}, {1, 1, -1});
  q.p1.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(q.run().hit);
}

TEST(VertexFaceCcd, BudgetGivesAConservativeHit) {
  PrimitiveCcdOptions options;
  options.max_boxes = 3;
  // Sliding in the face's plane into the face at t = 1/5: the coplanarity cubic vanishes
  // throughout, so no witness is found at the cubic's roots and the search runs out.
  const PrimitiveCcdResult r = still_triangle({-1, 1, 0}, {4, 1, 0}).run(options);
  EXPECT_TRUE(r.hit);
  EXPECT_TRUE(r.budget_exhausted);
  EXPECT_LE(r.toi, 1.0 / 5);
  // A crossing needs no budget in either mode: its witness proves the contact, and (for the
  // earliest one) the coplanarity cubic that nothing comes before it.
  options.max_boxes = 1;
  for (const bool earliest : {true, false}) {
    options.earliest = earliest;
    const PrimitiveCcdResult crossing = still_triangle({1, 1, 1}, {1, 1, -2}).run(options);
    EXPECT_TRUE(crossing.hit);
    EXPECT_FALSE(crossing.budget_exhausted);
    EXPECT_LE(crossing.toi, 1.0 / 3 + (earliest ? 0 : 1e-12));
    EXPECT_GT(crossing.toi, 1.0 / 3 - 1e-6);
  }
  // With a separation, near misses count as contacts and the cubic proves nothing: an
  // earliest query searches, and runs out.
  options.earliest = true;
  options.separation = 1e-3;
  EXPECT_TRUE(still_triangle({1, 1, 1}, {1, 1, -2}).run(options).budget_exhausted);
}

// ---- edge–edge: constructed ----------------------------------------------------------------

PrimitiveCcdResult ee(const Vector3d& a0, const Vector3d& b0, const Vector3d& c0, const Vector3d& d0,
                      const Vector3d& a1, const Vector3d& b1, const Vector3d& c1, const Vector3d& d1,
                      const PrimitiveCcdOptions& options = {}) {
  return edge_edge_ccd(a0, b0, c0, d0, a1, b1, c1, d1, options);
}

TEST(EdgeEdgeCcd, EdgesCrossAtOneHalf) {
  // Edge ab along x at z = 0; edge cd along y at z = 1 − 2t.
  const Vector3d a(-1, 0, 0), b(1, 0, 0);
  const PrimitiveCcdResult r = ee(a, b, {0, -1, 1}, {0, 1, 1}, a, b, {0, -1, -1}, {0, 1, -1});
  ASSERT_TRUE(r.hit);
  EXPECT_LE(r.toi, 0.5);
  EXPECT_GT(r.toi, 0.5 - 1e-6);
  const mpq_class half(1, 2);
  EXPECT_EQ(orient_exact(lerp_exact(a, a, half), lerp_exact(b, b, half), lerp_exact({0, -1, 1}, {0, -1, -1}, half),
                         lerp_exact({0, 1, 1}, {0, 1, -1}, half)),
            0);
  // Shifted past the end of ab: the lines cross, the segments do not.
  EXPECT_FALSE(ee(a, b, {1.001, -1, 1}, {1.001, 1, 1}, a, b, {1.001, -1, -1}, {1.001, 1, -1}).hit);
  // Grazing: cd's line passes exactly through b.
  EXPECT_TRUE(ee(a, b, {1, -1, 1}, {1, 1, 1}, a, b, {1, -1, -1}, {1, 1, -1}).hit);
}

TEST(EdgeEdgeCcd, ParallelAndCollinearEdges) {
  const Vector3d a(0, 0, 0), b(1, 0, 0);
  // Parallel, one sliding over the other at height 1e-3: never touch.
  EXPECT_FALSE(ee(a, b, {-3, 0, 1e-3}, {-2, 0, 1e-3}, a, b, {3, 0, 1e-3}, {4, 0, 1e-3}).hit);
  // Collinear, sliding through: touch (overlap) over an interval starting at t = 1/3.
  const PrimitiveCcdResult r = ee(a, b, {-3, 0, 0}, {-2, 0, 0}, a, b, {3, 0, 0}, {4, 0, 0});
  ASSERT_TRUE(r.hit);
  EXPECT_LE(r.toi, 1.0 / 3);
  EXPECT_GT(r.toi, 1.0 / 3 - 1e-6);
  // Collinear, moving together apart.
  EXPECT_FALSE(ee(a, b, {2, 0, 0}, {3, 0, 0}, {5, 5, 5}, {6, 5, 5}, {7, 5, 5}, {8, 5, 5}).hit);
  // End to end at the start.
  const PrimitiveCcdResult start = ee(a, b, {1, 0, 0}, {2, 0, 0}, a, b, {1, 1, 0}, {2, 1, 0});
  ASSERT_TRUE(start.hit);
  EXPECT_EQ(start.toi, 0.0);
}

TEST(EdgeEdgeCcd, DegenerateEdges) {
  const Vector3d a(0, 0, 0), b(2, 0, 0), o(1, -1, 0);
  // A point-edge passing through the segment, and missing it.
  EXPECT_TRUE(ee(a, b, o, o, a, b, {1, 1, 0}, {1, 1, 0}).hit);
  EXPECT_FALSE(ee(a, b, {3, -1, 0}, {3, -1, 0}, a, b, {3, 1, 0}, {3, 1, 0}).hit);
  // Two points meeting at t = 1/2, and two points passing 1e-3 apart.
  EXPECT_TRUE(ee(a, a, b, b, {2, 2, 2}, {2, 2, 2}, {0, 2, 2}, {0, 2, 2}).hit);
  EXPECT_FALSE(ee(a, a, b, b, {2, 2, 2}, {2, 2, 2}, {0, 2, 2.002}, {0, 2, 2.002}).hit);
}

// ---- randomized oracles ----------------------------------------------------------------------

/// Integer coordinates in [−range, range]; with t = k/256 every sampled position is exact.
Vector3d grid_point(std::mt19937& rng, int range) {
  std::uniform_int_distribution<int> coord(-range, range);
  return Vector3d(coord(rng), coord(rng), coord(rng));
}

/// Makes degeneracies frequent: sometimes flattens everything onto z = 0, or repeats a point.
void degenerate_sometimes(std::mt19937& rng, std::array<Vector3d, 8>& x) {
  const int mode = static_cast<int>(rng() % 5);
  if (mode == 0)
    for (auto& p : x) p.z() = 0;
  if (mode == 1) x[3] = x[2], x[7] = x[6];              // a repeated vertex
  if (mode == 2) x[4 + 1] = x[1] + (x[4] - x[0]), x[4 + 2] = x[2] + (x[4] - x[0]);  // parallel motion
}

constexpr int kSamples = 257;  // t = k / 256

TEST(PrimitiveCcdOracle, NoSampledContactIsMissedOnIntegerGrids) {
  std::mt19937 rng(20240611);
  int sampled_vf = 0, sampled_ee = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    std::array<Vector3d, 8> x;
    for (auto& p : x) p = grid_point(rng, 3);
    degenerate_sometimes(rng, x);
    const bool vf = trial % 2 == 0;
    int first = -1;
    for (int k = 0; k < kSamples && first < 0; ++k) {
      const double t = k / 256.0;
      std::array<Vector3d, 4> y;
      for (int i = 0; i < 4; ++i) y[i] = x[i] + t * (x[4 + i] - x[i]);  // exact
      const bool touch = vf ? triangles_intersect(y[0], y[0], y[0], y[1], y[2], y[3])
                            : triangles_intersect(y[0], y[0], y[1], y[2], y[2], y[3]);
      if (touch) first = k;
    }
    const PrimitiveCcdResult r = vf ? vertex_face_ccd(x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7])
                                    : edge_edge_ccd(x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]);
    PrimitiveCcdOptions whether;
    whether.earliest = false;
    const PrimitiveCcdResult w = vf ? vertex_face_ccd(x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], whether)
                                    : edge_edge_ccd(x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], whether);
    if (first >= 0) {
      (vf ? sampled_vf : sampled_ee)++;
      ASSERT_TRUE(r.hit) << "trial " << trial;
      EXPECT_LE(r.toi, first / 256.0) << "trial " << trial;
      ASSERT_TRUE(w.hit) << "trial " << trial;
    }
  }
  // The test means something only if contacts happen often enough.
  EXPECT_GT(sampled_vf, 50);
  EXPECT_GT(sampled_ee, 50);
}

TEST(PrimitiveCcdOracle, ConfigurationsSeparatedByAPlaneNeverHit) {
  // Everything of the vertex (or first edge) stays above z = h, the rest below z = 0, at both
  // ends and hence throughout: the gap is at least h > tolerance.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-1, 1);
  for (const double h : {1e-2, 1e-4, 1e-5}) {
    for (int trial = 0; trial < 500; ++trial) {
      std::array<Vector3d, 8> x;
      for (auto& p : x) p = Vector3d(coord(rng), coord(rng), -std::abs(coord(rng)));
      const bool vf = trial % 2 == 0;
      const int upper = vf ? 1 : 2;  // vertex 0, or vertices 0 and 1, are lifted
      for (int end = 0; end < 2; ++end)
        for (int i = 0; i < upper; ++i) x[4 * end + i].z() = h + std::abs(coord(rng)) * (trial % 3 == 0 ? 0 : 1);
      for (const bool earliest : {true, false}) {
        PrimitiveCcdOptions options;
        options.earliest = earliest;
        const PrimitiveCcdResult r = vf ? vertex_face_ccd(x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], options)
                                        : edge_edge_ccd(x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], options);
        ASSERT_FALSE(r.hit) << "h " << h << " trial " << trial << " earliest " << earliest;
      }
    }
  }
}

TEST(PrimitiveCcdOracle, RandomCrossingsAreFoundWithTheirTime) {
  // A random moving triangle and a vertex placed on it at a random time t*: the contact must
  // be found with toi ≤ t*. Positions at t* are exact rationals of the construction, so the
  // vertex is built from barycentric weights with the same motion and checked exactly.
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> coord(-1, 1);
  std::uniform_int_distribution<int> pick(1, 255);
  for (int trial = 0; trial < 500; ++trial) {
    std::array<Vector3d, 3> f0, f1;
    for (int i = 0; i < 3; ++i) f0[i] = Vector3d(coord(rng), coord(rng), coord(rng)), f1[i] = f0[i] + Vector3d(coord(rng), coord(rng), coord(rng));
    const double ts = pick(rng) / 256.0;
    // Barycentric point of the triangle at ts (exact weights 1/4, 1/4, 1/2 on dyadics is not
    // exact in general, so accept a contact computed in doubles: the vertex path then passes
    // within rounding of the face and the answer must still be a hit).
    Vector3d on = Vector3d::Zero();
    for (int i = 0; i < 3; ++i) on += (i == 2 ? 0.5 : 0.25) * (f0[i] + ts * (f1[i] - f0[i]));
    const Vector3d dir(coord(rng), coord(rng), coord(rng));
    const Vector3d p0 = on - ts * dir, p1 = on + (1 - ts) * dir;
    const PrimitiveCcdResult r = vertex_face_ccd(p0, f0[0], f0[1], f0[2], p1, f1[0], f1[1], f1[2]);
    ASSERT_TRUE(r.hit) << trial;
    EXPECT_LE(r.toi, ts + 1e-12) << trial;
  }
}

/// Smallest Euclidean length of F(u, v) = d + u e1 + v e2 over the vertex–face domain (the
/// triangle u, v ≥ 0, u + v ≤ 1) or the edge–edge one (the unit square): a convex quadratic,
/// so its minimum is the free minimum if inside, else on the boundary, where each side is
/// minimized by a clamped projection. Long double, for a reference well below the tolerance.
long double smallest_f(const Vector3d& d, const Vector3d& e1, const Vector3d& e2, bool simplex) {
  using V = Eigen::Matrix<long double, 3, 1>;
  const V dd = d.cast<long double>(), a = e1.cast<long double>(), b = e2.cast<long double>();
  const auto length = [&](long double u, long double v) { return (dd + u * a + v * b).norm(); };
  // On the segment from (u0, v0) to (u1, v1): F = f0 + s g, s ∈ [0, 1].
  const auto on_side = [&](long double u0, long double v0, long double u1, long double v1) {
    const V f0 = dd + u0 * a + v0 * b, g = (u1 - u0) * a + (v1 - v0) * b;
    const long double gg = g.squaredNorm();
    const long double s = gg > 0 ? std::clamp(-f0.dot(g) / gg, 0.0L, 1.0L) : 0.0L;
    return (f0 + s * g).norm();
  };
  long double best = simplex ? std::min({on_side(0, 0, 1, 0), on_side(1, 0, 0, 1), on_side(0, 1, 0, 0)})
                             : std::min({on_side(0, 0, 1, 0), on_side(1, 0, 1, 1), on_side(1, 1, 0, 1), on_side(0, 1, 0, 0)});
  const long double g11 = a.dot(a), g12 = a.dot(b), g22 = b.dot(b), det = g11 * g22 - g12 * g12;
  if (det > 0) {
    const long double r1 = -dd.dot(a), r2 = -dd.dot(b);
    const long double u = (r1 * g22 - r2 * g12) / det, v = (g11 * r2 - g12 * r1) / det;
    const bool inside = simplex ? u >= 0 && v >= 0 && u + v <= 1 : u >= 0 && v >= 0 && u <= 1 && v <= 1;
    if (inside) best = std::min(best, length(u, v));
  }
  return best;
}

TEST(PrimitiveCcdOracle, WhetherHitsHaveANearContactAtTheirTime) {
  // Crossings and passes at distances around the tolerance (1e-7 … 1e-5), in both kinds: a
  // "whether" hit (a witness or an accepted box) must come with primitives within
  // √3 (tolerance + 2e) of each other at its time `toi` (L∞ tolerance, Euclidean check).
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coord(-1, 1), unit(0, 1);
  PrimitiveCcdOptions options;
  options.earliest = false;
  int hits = 0, misses = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::array<Vector3d, 8> x;
    for (int k = 0; k < 4; ++k) x[k] = Vector3d(coord(rng), coord(rng), coord(rng)), x[4 + k] = x[k] + 0.5 * Vector3d(coord(rng), coord(rng), coord(rng));
    const bool vf = trial % 2 == 0;
    // Put F through (near) zero at a random time: shift the first primitive by F(t*, u*, v*)
    // minus a random offset of length 1e-7 … 1e-5 (often 0).
    const double ts = unit(rng), us = 0.5 * unit(rng), vs = 0.5 * unit(rng);
    const auto at = [&](int k) { return Vector3d(x[k] + ts * (x[4 + k] - x[k])); };
    const Vector3d f = vf ? Vector3d(at(0) - at(1) - us * (at(2) - at(1)) - vs * (at(3) - at(1)))
                          : Vector3d(at(0) + us * (at(1) - at(0)) - at(2) - vs * (at(3) - at(2)));
    const Vector3d offset = trial % 3 == 0 ? Vector3d(Vector3d::Zero())
                                           : Vector3d(std::pow(10.0, -7 + 2 * unit(rng)) * Vector3d(coord(rng), coord(rng), coord(rng)).normalized());
    for (int k = 0; k < (vf ? 1 : 2); ++k) x[k] += offset - f, x[4 + k] += offset - f;
    const PrimitiveCcdResult r = vf ? vertex_face_ccd(x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], options)
                                    : edge_edge_ccd(x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], options);
    if (!r.hit) {
      ++misses;
      continue;
    }
    ++hits;
    const double t = r.toi;
    ASSERT_GE(t, 0.0);
    ASSERT_LE(t, 1.0);
    const auto pos = [&](int k) { return Vector3d(x[k] + t * (x[4 + k] - x[k])); };
    const long double gap = vf ? smallest_f(pos(0) - pos(1), pos(1) - pos(2), pos(1) - pos(3), true)
                               : smallest_f(pos(0) - pos(2), pos(1) - pos(0), pos(2) - pos(3), false);
    EXPECT_LE(gap, std::sqrt(3.0) * (options.tolerance + 1e-12)) << "trial " << trial << " t " << t;
  }
  // Most are hits (the offset rarely moves the contact away: the paths still cross).
  EXPECT_GT(hits, 2000);
  EXPECT_EQ(hits + misses, 3000);
}

TEST(PrimitiveCcdOracle, PassesJustBeyondTheToleranceMiss) {
  // Sliding parallel at L∞ distance 2 × tolerance, in both query modes: neither the box
  // search nor a witness may call that a contact (the bound is tolerance + 2e).
  for (const bool earliest : {true, false}) {
    PrimitiveCcdOptions options;
    options.earliest = earliest;
    const double h = 2 * options.tolerance;
    EXPECT_FALSE(still_triangle({-1, 1, h}, {4, 1, h}).run(options).hit) << earliest;
    EXPECT_FALSE(still_triangle({1, 1, 1}, {1, 1, h}).run(options).hit) << earliest;
    const Vector3d a(-1, 0, 0), b(1, 0, 0);
    EXPECT_FALSE(ee(a, b, {0, -1, h}, {0, 1, h}, a, b, {0.5, -1, h}, {0.5, 1, h}, options).hit) << earliest;
    EXPECT_FALSE(ee(a, b, {1 + h, -1, 1}, {1 + h, 1, 1}, a, b, {1 + h, -1, -1}, {1 + h, 1, -1}, options).hit)
        << earliest;
  }
}

}  // namespace
}  // namespace reconfig::collision
