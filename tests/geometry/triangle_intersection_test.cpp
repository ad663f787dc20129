#include "reconfig/geometry/triangle_intersection.h"

#include <CGAL/Gmpq.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "exact_kernels_test_util.h"

namespace reconfig::geometry {
namespace {

using Eigen::Vector3d;
using Tri = std::array<Vector3d, 3>;

// ---------------------------------------------------------------------------------------------
// Oracle: separating-axis test in exact arithmetic (int64 on integer grids, Gmpq for doubles).
// Two compact convex sets are disjoint iff some direction strictly separates their projections.
// For (possibly degenerate) triangles A, B the facet normals of the Minkowski difference A − B,
// within its affine hull, are among u, u×w and (u×w)×x with u, w drawn from
// D = {edges of A, edges of B, a_i − b_j} and x from the edges: this covers the full 3D case
// (nA, nB, eA×eB), the flat cases (in-plane edge normals n×e), collinear cases ((e×m)×e, e)
// and points (a − b). Extra axes cannot make the test wrong, only slower.
// ---------------------------------------------------------------------------------------------

template <class T>
using V3 = std::array<T, 3>;

template <class T>
V3<T> sub(const V3<T>& a, const V3<T>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
template <class T>
V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class T>
T dot(const V3<T>& a, const V3<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class T>
bool is_zero(const V3<T>& a) {
  return a[0] == 0 && a[1] == 0 && a[2] == 0;
}

template <class T>
bool oracle_intersect(const std::array<V3<T>, 3>& A, const std::array<V3<T>, 3>& B) {
  std::vector<V3<T>> edges, dirs;
  for (int i = 0; i < 3; ++i) {
    edges.push_back(sub(A[(i + 1) % 3], A[i]));
    edges.push_back(sub(B[(i + 1) % 3], B[i]));
  }
  dirs = edges;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) dirs.push_back(sub(A[i], B[j]));
  const auto separates = [&](const V3<T>& axis) {
    if (is_zero(axis)) return false;
    T amin = dot(axis, A[0]), amax = amin, bmin = dot(axis, B[0]), bmax = bmin;
    for (int i = 1; i < 3; ++i) {
      const T a = dot(axis, A[i]), b = dot(axis, B[i]);
      amin = std::min(amin, a);
      amax = std::max(amax, a);
      bmin = std::min(bmin, b);
      bmax = std::max(bmax, b);
    }
    return amax < bmin || bmax < amin;
  };
  for (size_t i = 0; i < dirs.size(); ++i) {
    if (separates(dirs[i])) return false;
    for (size_t j = i + 1; j < dirs.size(); ++j) {
      const V3<T> c = cross(dirs[i], dirs[j]);
      if (is_zero(c)) continue;
      if (separates(c)) return false;
      for (const V3<T>& e : edges)
        if (separates(cross(c, e))) return false;
    }
  }
  return true;
}

/// All six points in one plane (exact).
template <class T>
bool oracle_coplanar(const std::array<V3<T>, 3>& A, const std::array<V3<T>, 3>& B) {
  std::vector<V3<T>> d;
  for (int i = 1; i < 3; ++i) d.push_back(sub(A[i], A[0]));
  for (int i = 0; i < 3; ++i) d.push_back(sub(B[i], A[0]));
  for (size_t i = 0; i < d.size(); ++i)
    for (size_t j = i + 1; j < d.size(); ++j)
      for (size_t k = j + 1; k < d.size(); ++k)
        if (dot(cross(d[i], d[j]), d[k]) != 0) return false;
  return true;
}

template <class T>
std::array<V3<T>, 3> to_exact(const Tri& t) {
  std::array<V3<T>, 3> r;
  for (int i = 0; i < 3; ++i)
    for (int d = 0; d < 3; ++d) {
      if constexpr (std::is_same_v<T, std::int64_t>) {
        r[i][d] = static_cast<std::int64_t>(t[i][d]);
      } else {
        r[i][d] = T(t[i][d]);  // Gmpq from double is exact
      }
    }
  return r;
}

bool intersect(const Tri& a, const Tri& b) { return triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2]); }
TriangleContact contact(const Tri& a, const Tri& b) { return intersect_triangles(a[0], a[1], a[2], b[0], b[1], b[2]); }

/// Points returned lie on both triangles; an intersecting pair reports 1..6 points, at most 2
/// when not coplanar; every corner of a proper triangle lying in the other one is reported.
void expect_consistent(const Tri& a, const Tri& b, const TriangleContact& c, bool oracle_coplanar_flag) {
  if (!c.intersect) {
    EXPECT_TRUE(c.points.empty());
    return;
  }
  ASSERT_GE(c.points.size(), 1u);
  ASSERT_LE(c.points.size(), 6u);
  if (!c.coplanar) {
    EXPECT_LE(c.points.size(), 2u);
    // The ends of the shared segment lie on the boundary of one of the triangles (so a
    // shortened segment cannot pass).
    const auto on_boundary = [](const Vector3d& p, const Tri& t) {
      return std::min({testing::distance_to_segment(p, t[0], t[1]), testing::distance_to_segment(p, t[1], t[2]),
                       testing::distance_to_segment(p, t[2], t[0])}) <= 1e-9;
    };
    for (const Vector3d& p : c.points) EXPECT_TRUE(on_boundary(p, a) || on_boundary(p, b)) << p.transpose();
  }
  EXPECT_EQ(c.coplanar, oracle_coplanar_flag);
  for (const Vector3d& p : c.points) {
    EXPECT_LE(testing::distance_to_triangle(p, a[0], a[1], a[2]), 1e-9);
    EXPECT_LE(testing::distance_to_triangle(p, b[0], b[1], b[2]), 1e-9);
  }
  if (c.points.size() >= 3) {  // a convex polygon in order: every turn has the same sense
    Vector3d normal = Vector3d::Zero();
    const size_t n = c.points.size();
    for (size_t i = 0; i < n; ++i) normal += c.points[i].cross(c.points[(i + 1) % n]);  // Newell
    for (size_t i = 0; i < n; ++i) {
      const Vector3d& p = c.points[i];
      const Vector3d& q = c.points[(i + 1) % n];
      const Vector3d& r = c.points[(i + 2) % n];
      EXPECT_GT((q - p).cross(r - q).dot(normal), 0) << "polygon not convex in order, vertex " << i;
    }
  }
  const auto reported = [&](const Vector3d& q) {
    return std::any_of(c.points.begin(), c.points.end(), [&](const Vector3d& p) { return (p - q).norm() <= 1e-9; });
  };
  const auto check_corners = [&](const Tri& s, const Tri& t) {
    if ((s[1] - s[0]).cross(s[2] - s[0]).squaredNorm() == 0) return;  // corners of a flat one may be inner
    for (const Vector3d& q : s) {
      const Tri point{q, q, q};
      if (intersect(point, t)) {
        EXPECT_TRUE(reported(q)) << "corner " << q.transpose() << " in other triangle";
      }
    }
  };
  check_corners(a, b);
  check_corners(b, a);
}

Tri random_grid_triangle(std::mt19937& rng, int lo, int hi) {
  std::uniform_int_distribution<int> coord(lo, hi);
  Tri t;
  for (auto& p : t) p = Vector3d(coord(rng), coord(rng), coord(rng));
  return t;
}

/// Random pairs on a small integer grid, with frequent shared planes, shared corners and
/// collapsed triangles.
std::pair<Tri, Tri> random_grid_pair(std::mt19937& rng) {
  std::uniform_int_distribution<int> kind(0, 5);
  Tri a = random_grid_triangle(rng, -2, 2), b = random_grid_triangle(rng, -2, 2);
  std::uniform_int_distribution<int> corner(0, 2);
  switch (kind(rng)) {
    case 0:  // coplanar in z = 0
      for (auto& p : a) p.z() = 0;
      for (auto& p : b) p.z() = 0;
      break;
    case 1:  // a shared corner
      b[corner(rng)] = a[corner(rng)];
      break;
    case 2:  // a shared edge (possibly flipped)
      b[0] = a[0];
      b[1] = a[1];
      if (corner(rng) == 0) std::swap(b[0], b[1]);
      break;
    case 3:  // a collapsed triangle: repeated corner or collinear corners
      if (corner(rng) == 0) {
        a[2] = a[corner(rng) % 2];
      } else {
        a[2] = a[0] + 2.0 * (a[1] - a[0]);
      }
      break;
    case 4:  // coplanar in x = 1, one of them collapsed to a point
      for (auto& p : a) p.x() = 1;
      for (auto& p : b) p.x() = 1;
      if (corner(rng) == 0) b[1] = b[2] = b[0];
      break;
    default:
      break;
  }
  return {a, b};
}

TEST(TriangleIntersection, MatchesExactOracleOnIntegerGrid) {
  std::mt19937 rng(1234);
  int hits = 0, coplanar_hits = 0;
  constexpr int kPairs = 4000;
  for (int trial = 0; trial < kPairs; ++trial) {
    const auto [a, b] = random_grid_pair(rng);
    const auto ea = to_exact<std::int64_t>(a), eb = to_exact<std::int64_t>(b);
    const bool expected = oracle_intersect(ea, eb);
    ASSERT_EQ(intersect(a, b), expected) << "trial " << trial << "\na: " << a[0].transpose() << " | "
                                         << a[1].transpose() << " | " << a[2].transpose() << "\nb: " << b[0].transpose()
                                         << " | " << b[1].transpose() << " | " << b[2].transpose();
    const TriangleContact c = contact(a, b);
    ASSERT_EQ(c.intersect, expected) << "trial " << trial;
    EXPECT_EQ(c.coplanar, oracle_coplanar(ea, eb)) << "trial " << trial;
    expect_consistent(a, b, c, oracle_coplanar(ea, eb));
    hits += expected;
    coplanar_hits += expected && c.coplanar;
  }
  // The generator must exercise both outcomes and the coplanar branch substantially.
  EXPECT_GT(hits, kPairs / 5);
  EXPECT_LT(hits, kPairs * 4 / 5);
  EXPECT_GT(coplanar_hits, kPairs / 20);
}

TEST(TriangleIntersection, MatchesRationalOracleOnPerturbedDoubles) {
  // Near-degenerate configurations in doubles: grid pairs with corners nudged by a few ulps
  // or 1e-15, decided against the oracle in exact rationals (Gmpq holds every double exactly).
  std::mt19937 rng(99);
  std::uniform_int_distribution<int> which(0, 5), sign(0, 1);
  std::uniform_real_distribution<double> scale(0.3, 3.0);
  for (int trial = 0; trial < 25; ++trial) {
    auto [a, b] = random_grid_pair(rng);
    const double s = scale(rng);
    for (auto& p : a) p *= s;
    for (auto& p : b) p *= s;
    Vector3d& moved = which(rng) < 3 ? a[which(rng) % 3] : b[which(rng) % 3];
    const int axis = which(rng) % 3;
    moved[axis] = sign(rng) ? std::nextafter(moved[axis], 10.0) : moved[axis] + 1e-15;
    const bool expected = oracle_intersect(to_exact<CGAL::Gmpq>(a), to_exact<CGAL::Gmpq>(b));
    ASSERT_EQ(intersect(a, b), expected) << "trial " << trial;
    const TriangleContact c = contact(a, b);
    ASSERT_EQ(c.intersect, expected);
    expect_consistent(a, b, c, oracle_coplanar(to_exact<CGAL::Gmpq>(a), to_exact<CGAL::Gmpq>(b)));
  }
}

TEST(TriangleIntersection, NearMissesInGeneralPositionMatchTheRationalOracle) {
  // Transversal pairs whose intersection segments end within 1e-16..1e-8 of each other, on
  // either side: the fast path in doubles must give up rather than guess.
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> coord(-1.0, 1.0), along(0.1, 0.9), exponent(-16.0, -8.0);
  int hits = 0, misses = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Tri a{Vector3d(coord(rng), coord(rng), coord(rng)), Vector3d(coord(rng), coord(rng), coord(rng)),
                Vector3d(coord(rng), coord(rng), coord(rng))};
    const Vector3d n = (a[1] - a[0]).cross(a[2] - a[0]).normalized();
    const Vector3d edge = (a[1] - a[0]).normalized();
    Vector3d outward = n.cross(edge);
    if (outward.dot(a[2] - a[0]) > 0) outward = -outward;
    const double gap = (trial % 2 ? 1.0 : -1.0) * std::pow(10.0, exponent(rng));
    const Vector3d p = a[0] + along(rng) * (a[1] - a[0]) + gap * outward;
    const Vector3d away = outward + 0.3 * coord(rng) * edge;
    const Tri b{p + 0.5 * n, p - 0.7 * n, p + 0.2 * coord(rng) * n + away};
    const bool expected = oracle_intersect(to_exact<CGAL::Gmpq>(a), to_exact<CGAL::Gmpq>(b));
    ASSERT_EQ(intersect(a, b), expected) << "trial " << trial;
    const TriangleContact c = contact(a, b);
    ASSERT_EQ(c.intersect, expected) << "trial " << trial;
    expect_consistent(a, b, c, oracle_coplanar(to_exact<CGAL::Gmpq>(a), to_exact<CGAL::Gmpq>(b)));
    (expected ? hits : misses) += 1;
  }
  EXPECT_GT(hits, 50);  // both sides of the edge are exercised
  EXPECT_GT(misses, 50);
}

TEST(TriangleIntersection, ContactsOfRandomDoubleTriangles) {
  // General position (the fast transversal construction) and thin slivers, at several scales
  // and offsets from the origin.
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int hits = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const double scale = std::pow(10.0, trial % 7 - 3);
    const Vector3d offset = Vector3d(unit(rng), unit(rng), unit(rng)) * scale * (trial % 3 == 0 ? 1e3 : 1.0);
    Tri a, b;
    for (auto& p : a) p = offset + scale * Vector3d(unit(rng), unit(rng), unit(rng));
    for (auto& p : b) p = offset + scale * Vector3d(unit(rng), unit(rng), unit(rng));
    if (trial % 5 == 0) a[2] = a[0] + (a[1] - a[0]) * 0.5 + scale * 1e-7 * Vector3d(unit(rng), unit(rng), unit(rng));
    const TriangleContact c = contact(a, b);
    hits += c.intersect;
    ASSERT_EQ(c.intersect, intersect(a, b));
    if (!c.intersect) continue;
    // Rescale to unit size for the 1e-9 checks.
    Tri ua = a, ub = b;
    for (auto& p : ua) p = (p - offset) / scale;
    for (auto& p : ub) p = (p - offset) / scale;
    TriangleContact uc = c;
    for (auto& p : uc.points) p = (p - offset) / scale;
    expect_consistent(ua, ub, uc, oracle_coplanar(to_exact<CGAL::Gmpq>(a), to_exact<CGAL::Gmpq>(b)));
    if (::testing::Test::HasFailure()) FAIL() << "trial " << trial;
  }
  EXPECT_GT(hits, 300);
}

TEST(TriangleIntersection, SymmetricUnderSwapAndCornerPermutation) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  const std::array<std::array<int, 3>, 6> perms{{{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (int trial = 0; trial < 100; ++trial) {
    auto [a, b] = random_grid_pair(rng);
    if (trial % 2) {  // also arbitrary doubles
      for (auto& p : a) p += Vector3d(coord(rng), coord(rng), coord(rng)) * 0.5;
      for (auto& p : b) p += Vector3d(coord(rng), coord(rng), coord(rng)) * 0.5;
    }
    const bool expected = intersect(a, b);
    const TriangleContact reference = contact(a, b);
    for (const auto& pa : perms)
      for (const auto& pb : perms) {
        const Tri a2{a[pa[0]], a[pa[1]], a[pa[2]]}, b2{b[pb[0]], b[pb[1]], b[pb[2]]};
        ASSERT_EQ(intersect(a2, b2), expected);
        ASSERT_EQ(intersect(b2, a2), expected);
        const TriangleContact c = contact(b2, a2);
        ASSERT_EQ(c.intersect, expected);
        ASSERT_EQ(c.coplanar, reference.coplanar);
        ASSERT_EQ(c.points.size(), reference.points.size());
      }
  }
}

TEST(TriangleIntersection, HandMadeCases) {
  const Vector3d o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  const Tri base{o, x, y};
  // Coplanar overlapping: a quadrilateral overlap (4 points).
  {
    const Tri b{Vector3d(0.25, -0.5, 0), Vector3d(0.25, 1, 0), Vector3d(-1, 0.25, 0)};
    const TriangleContact c = contact(base, b);
    EXPECT_TRUE(c.intersect);
    EXPECT_TRUE(c.coplanar);
    EXPECT_GE(c.points.size(), 3u);
    expect_consistent(base, b, c, true);
  }
  // Coplanar touching at one vertex only.
  {
    const Tri b{x, Vector3d(2, 0, 0), Vector3d(2, -1, 0)};
    const TriangleContact c = contact(base, b);
    EXPECT_TRUE(c.intersect);
    EXPECT_TRUE(c.coplanar);
    ASSERT_EQ(c.points.size(), 1u);
    EXPECT_EQ(c.points[0], x);
  }
  // Coplanar, separated by a hair.
  EXPECT_FALSE(intersect(base, Tri{Vector3d(0.5 + 1e-15, 0.5 + 1e-15, 0), Vector3d(2, 2, 0), Vector3d(2, 0.6, 0)}));
  EXPECT_TRUE(intersect(base, Tri{Vector3d(0.5, 0.5, 0), Vector3d(2, 2, 0), Vector3d(2, 0.6, 0)}));
  // Edge–edge crossing (non-coplanar): the contact is one point.
  {
    const Tri b{Vector3d(0.75, 0.75, -1), Vector3d(0.25, 0.25, 1), Vector3d(2, 2, 0)};
    const TriangleContact c = contact(base, b);
    EXPECT_TRUE(c.intersect);
    EXPECT_FALSE(c.coplanar);
    ASSERT_EQ(c.points.size(), 1u);
    EXPECT_LE((c.points[0] - Vector3d(0.5, 0.5, 0)).norm(), 1e-15);
  }
  // Piercing: an edge through the interior, the triangle leaves through an edge.
  {
    const Tri b{Vector3d(0.25, 0.25, -1), Vector3d(0.25, 0.25, 1), Vector3d(5, 5, 0)};
    const TriangleContact c = contact(base, b);
    EXPECT_TRUE(c.intersect);
    EXPECT_FALSE(c.coplanar);
    ASSERT_EQ(c.points.size(), 2u);  // b's edge pierces the interior of base, b crosses base's hypotenuse
    expect_consistent(base, b, c, false);
  }
  {
    const Tri b{Vector3d(0.5, 0.5, 0), Vector3d(0.5, 0.5, 1), Vector3d(1, 1, 1)};  // touches the edge x–y at its middle
    const TriangleContact c = contact(base, b);
    EXPECT_TRUE(c.intersect);
    ASSERT_EQ(c.points.size(), 1u);
    EXPECT_LE((c.points[0] - Vector3d(0.5, 0.5, 0)).norm(), 1e-15);
  }
  // Vertex on face, and the same vertex lifted by 1e-15.
  EXPECT_TRUE(intersect(base, Tri{Vector3d(0.2, 0.2, 0), Vector3d(0, 0, 1), Vector3d(1, 1, 1)}));
  EXPECT_FALSE(intersect(base, Tri{Vector3d(0.2, 0.2, 1e-15), Vector3d(0, 0, 1), Vector3d(1, 1, 1)}));
  EXPECT_FALSE(intersect(base, Tri{Vector3d(0.2, 0.2, 1e-300), Vector3d(0, 0, 1), Vector3d(1, 1, 1)}));
  // Parallel planes.
  EXPECT_FALSE(intersect(base, Tri{Vector3d(0, 0, 1e-15), Vector3d(1, 0, 1e-15), Vector3d(0, 1, 1e-15)}));
  // Degenerate: a segment piercing the face, a segment above it, a point on an edge, a point off it.
  EXPECT_TRUE(intersect(base, Tri{Vector3d(0.3, 0.3, -1), Vector3d(0.3, 0.3, 1), Vector3d(0.3, 0.3, 0.5)}));
  EXPECT_FALSE(intersect(base, Tri{Vector3d(0.3, 0.3, 0.1), Vector3d(0.3, 0.3, 1), Vector3d(0.3, 0.3, 0.5)}));
  EXPECT_TRUE(intersect(base, Tri{Vector3d(0.5, 0, 0), Vector3d(0.5, 0, 0), Vector3d(0.5, 0, 0)}));
  EXPECT_FALSE(intersect(base, Tri{Vector3d(0.5, -1e-300, 0), Vector3d(0.5, -1e-300, 0), Vector3d(0.5, -1e-300, 0)}));
  // Two collapsed triangles: collinear overlapping segments, crossing segments, skew segments.
  EXPECT_TRUE(intersect(Tri{o, x, x}, Tri{Vector3d(0.5, 0, 0), Vector3d(2, 0, 0), Vector3d(3, 0, 0)}));
  EXPECT_FALSE(intersect(Tri{o, x, x}, Tri{Vector3d(1.5, 0, 0), Vector3d(2, 0, 0), Vector3d(3, 0, 0)}));
  EXPECT_TRUE(intersect(Tri{o, x, x}, Tri{Vector3d(0.5, -1, 0), Vector3d(0.5, 1, 0), Vector3d(0.5, 1, 0)}));
  EXPECT_FALSE(intersect(Tri{o, x, x}, Tri{Vector3d(0.5, -1, 1e-15), Vector3d(0.5, 1, 1e-15), Vector3d(0.5, 1, 0)}));
  {
    const TriangleContact c = contact(Tri{o, x, x}, Tri{Vector3d(0.5, 0, 0), Vector3d(2, 0, 0), Vector3d(3, 0, 0)});
    ASSERT_EQ(c.points.size(), 2u);
    EXPECT_TRUE(c.coplanar);
  }
  // Identical triangles, and a triangle with itself flipped.
  EXPECT_EQ(contact(base, base).points.size(), 3u);
  EXPECT_TRUE(intersect(base, Tri{y, x, o}));
  // Non-finite input never intersects.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(intersect(base, Tri{Vector3d(nan, 0, 0), x, y}));
  EXPECT_FALSE(intersect(base, Tri{Vector3d(-INFINITY, 0, 0), Vector3d(INFINITY, 0, 0), z}));
}

TEST(TriangleIntersection, FastOnMostlyDisjointPairs) {
  // A smoke check of the cheap path: a million pairs, most of them with overlapping boxes
  // but no contact, must take well under a second in Release.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coord(0.0, 1.0);
  std::vector<Tri> tris(2000);
  for (auto& t : tris) {
    const Vector3d c(coord(rng), coord(rng), coord(rng));
    for (auto& p : t) p = c + 0.3 * Vector3d(coord(rng), coord(rng), coord(rng));
  }
  const auto start = std::chrono::steady_clock::now();
  int hits = 0;
  for (int i = 0; i < 1000; ++i)
    for (int j = 1000; j < 2000; ++j) hits += intersect(tris[i], tris[j]);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("seconds_per_million", std::to_string(seconds));
  EXPECT_GT(hits, 0);
#ifdef NDEBUG
  EXPECT_LT(seconds, 2.0);
#endif
}

}  // namespace
}  // namespace reconfig::geometry
