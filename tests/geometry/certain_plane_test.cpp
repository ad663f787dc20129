#include "reconfig/geometry/certain_plane.h"

#include <CGAL/Gmpq.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <random>

namespace reconfig::geometry {
namespace {

using Q = CGAL::Gmpq;

/// The exact sign of orient(p0, p1, p2, q) = ((p1 − p0) × (p2 − p0)) · (q − p0), in rationals.
int exact_side(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
               const Eigen::Vector3d& q) {
  const auto diff = [](const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
    return std::array<Q, 3>{Q(x.x()) - Q(y.x()), Q(x.y()) - Q(y.y()), Q(x.z()) - Q(y.z())};
  };
  const std::array<Q, 3> e1 = diff(p1, p0), e2 = diff(p2, p0), d = diff(q, p0);
  const Q n0 = e1[1] * e2[2] - e1[2] * e2[1], n1 = e1[2] * e2[0] - e1[0] * e2[2], n2 = e1[0] * e2[1] - e1[1] * e2[0];
  const Q s = n0 * d[0] + n1 * d[1] + n2 * d[2];
  return s > 0 ? 1 : (s < 0 ? -1 : 0);
}

struct Case {
  std::array<Eigen::Vector3d, 3> plane;
  Eigen::Vector3d q;
};

/// A random triangle (sometimes a sliver or far from the origin) and a point on its plane
/// moved off it by a random, often tiny, amount: the cases where rounding decides.
Case random_case(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> exponent(-60, 0);
  const auto point = [&] { return Eigen::Vector3d(unit(rng), unit(rng), unit(rng)); };
  const double scale = std::ldexp(1.0, exponent(rng) / 6), shift = rng() % 3 == 0 ? 1e3 : 0.0;
  Case c;
  c.plane = {scale * point(), scale * point(), scale * point()};
  if (rng() % 4 == 0) c.plane[2] = c.plane[0] + std::ldexp(1.0, exponent(rng)) * (c.plane[1] - c.plane[0]) + 1e-9 * scale * point();
  for (Eigen::Vector3d& p : c.plane) p.array() += shift;
  const double u = unit(rng), v = unit(rng);
  const Eigen::Vector3d on = c.plane[0] + u * (c.plane[1] - c.plane[0]) + v * (c.plane[2] - c.plane[0]);
  const Eigen::Vector3d n = (c.plane[1] - c.plane[0]).cross(c.plane[2] - c.plane[0]);
  const double off = rng() % 5 == 0 ? 0.0 : std::ldexp(unit(rng), exponent(rng));
  c.q = on + off * (n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : point());
  return c;
}

TEST(CertainPlane, NeverContradictsTheExactOrientation) {
  std::mt19937 rng(7);
  int decided = 0, undecided = 0;
  for (int i = 0; i < 200000; ++i) {
    const Case c = random_case(rng);
    const int side = certain_side(certain_plane(c.plane[0], c.plane[1], c.plane[2]), c.q);
    if (side == 0) {
      ++undecided;
      continue;
    }
    ++decided;
    ASSERT_EQ(side, exact_side(c.plane[0], c.plane[1], c.plane[2], c.q)) << "case " << i;
  }
  // The filter must decide most cases (else it filters nothing) and leave some to the exact test.
  EXPECT_GT(decided, 100000);
  EXPECT_GT(undecided, 1000);
}

TEST(CertainPlane, ClearCasesAreDecidedAndTouchingOnesAreNot) {
  const Eigen::Vector3d p0(0, 0, 0), p1(1, 0, 0), p2(0, 1, 0);
  const CertainPlane plane = certain_plane(p0, p1, p2);
  EXPECT_EQ(certain_side(plane, {0.2, 0.2, 1e-3}), 1);
  EXPECT_EQ(certain_side(plane, {0.2, 0.2, -1e-3}), -1);
  EXPECT_EQ(certain_side(plane, {5, -3, 0}), 0);                     // on the plane
  EXPECT_EQ(certain_side(plane, {0.2, 0.2, std::nan("")}), 0);       // NaN
  EXPECT_EQ(certain_side(certain_plane(p0, p1, 2 * p1), {0, 0, 1}), 0);  // a degenerate triangle
  // Where rounding could underflow, no answer: a triangle of 1e-120 edges, a point 1e-120 off.
  EXPECT_EQ(certain_side(certain_plane(p0, 1e-120 * p1, 1e-120 * p2), {0, 0, 1}), 0);
  EXPECT_EQ(certain_side(plane, {0, 0, 1e-120}), 0);
  EXPECT_EQ(certain_side(plane, {0, 0, 1e-90}), 1);
  const auto sides = [&](const Eigen::Vector3d& q0, const Eigen::Vector3d& q1, const Eigen::Vector3d& q2) {
    return certain_sides(plane, {q0, q1, q2});
  };
  EXPECT_EQ(sides({0, 0, 1}, {1, 1, 2}, {-1, 0, 0.5}), (KnownSides{1, 1, 1}));
  EXPECT_TRUE(all_on_one_side(sides({0, 0, 1}, {1, 1, 2}, {-1, 0, 0.5})));
  EXPECT_EQ(sides({0, 0, 1}, {1, 1, -2}, {-1, 0, 0.5}), (KnownSides{1, -1, 1}));
  EXPECT_FALSE(all_on_one_side(sides({0, 0, 1}, {1, 1, -2}, {-1, 0, 0.5})));
  EXPECT_EQ(sides({0, 0, 1}, {1, 1, 0}, {-1, 0, 0.5}), (KnownSides{1, 0, 1}));
  EXPECT_FALSE(all_on_one_side(sides({0, 0, 1}, {1, 1, 0}, {-1, 0, 0.5})));
}

/// A random triangle: on a small integer grid half the time (touching, coplanar, shared and
/// degenerate corners are common there), else of random doubles in a unit box.
std::array<Eigen::Vector3d, 3> random_triangle(std::mt19937& rng) {
  std::uniform_int_distribution<int> grid(-2, 2);
  std::uniform_real_distribution<double> unit(-1, 1);
  const bool on_grid = rng() % 2 == 0;
  std::array<Eigen::Vector3d, 3> t;
  for (Eigen::Vector3d& p : t)
    p = on_grid ? Eigen::Vector3d(grid(rng), grid(rng), grid(rng)) : Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
  return t;
}

TEST(CertainPlane, KnownSidesGiveTheContactTheExactTestGives) {
  std::mt19937 rng(11);
  int crossing = 0, with_known = 0;
  for (int i = 0; i < 100000; ++i) {
    const std::array<Eigen::Vector3d, 3> a = random_triangle(rng), b = random_triangle(rng);
    const KnownSides side_a = certain_sides(certain_plane(b[0], b[1], b[2]), a);
    const KnownSides side_b = certain_sides(certain_plane(a[0], a[1], a[2]), b);
    with_known += side_a != KnownSides{0, 0, 0} || side_b != KnownSides{0, 0, 0};
    const TriangleContact expected = intersect_triangles(a[0], a[1], a[2], b[0], b[1], b[2]);
    const TriangleContact got = intersect_triangles(a[0], a[1], a[2], b[0], b[1], b[2], side_a, side_b);
    crossing += expected.intersect && !expected.coplanar && expected.points.size() == 2;
    ASSERT_EQ(got.intersect, expected.intersect) << "case " << i;
    ASSERT_EQ(got.coplanar, expected.coplanar) << "case " << i;
    ASSERT_EQ(got.points, expected.points) << "case " << i;
  }
  EXPECT_GT(crossing, 5000);     // the contour's case is well represented
  EXPECT_GT(with_known, 50000);  // and most pairs come with sides known
}

}  // namespace
}  // namespace reconfig::geometry
