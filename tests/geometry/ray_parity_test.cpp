#include "reconfig/geometry/ray_parity.h"

#include <CGAL/Gmpq.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>

#include "reconfig/geometry/point_in_solid.h"
#include "reconfig/geometry/primitives.h"

namespace reconfig::geometry {
namespace {

using Q = CGAL::Gmpq;
using Eigen::Vector3d;

/// The exact sign of the 2D orientation of (a, b, c) on coordinates (i, j), in rationals.
int exact_orientation_2d(const Vector3d& a, const Vector3d& b, const Vector3d& c, int i, int j) {
  const Q det = (Q(a[i]) - Q(c[i])) * (Q(b[j]) - Q(c[j])) - (Q(a[j]) - Q(c[j])) * (Q(b[i]) - Q(c[i]));
  return det > 0 ? 1 : (det < 0 ? -1 : 0);
}

TEST(RayParity, OrientationNeverContradictsTheExactOne) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> exponent(-60, 0);
  int decided = 0, undecided = 0;
  for (int n = 0; n < 200000; ++n) {
    const Vector3d a(unit(rng), unit(rng), unit(rng)), b(unit(rng), unit(rng), unit(rng));
    // c on the line ab (in the projection) moved off it by a random, often tiny, amount.
    const double u = 3 * unit(rng), off = rng() % 5 == 0 ? 0.0 : std::ldexp(unit(rng), exponent(rng));
    Vector3d c = a + u * (b - a);
    c[1] += off;
    c[0] = unit(rng);
    const int i = 1 + static_cast<int>(rng() % 2), j = i == 1 ? 2 : 1;
    const int o = certain_orientation_2d(a, b, c, i, j);
    if (o == 0) {
      ++undecided;
      continue;
    }
    ++decided;
    ASSERT_EQ(o, exact_orientation_2d(a, b, c, i, j)) << "case " << n;
  }
  EXPECT_GT(decided, 100000);  // it decides most cases
  EXPECT_GT(undecided, 1000);  // and leaves the collinear and near-collinear ones
}

/// A closed, irregular, star-shaped mesh: a sphere with every vertex moved along its ray.
Mesh lumpy_sphere(std::mt19937& rng) {
  Mesh mesh = make_sphere(0.5, 3);
  std::uniform_real_distribution<double> radius(0.6, 1.4);
  for (int v = 0; v < mesh.vertex_count(); ++v) mesh.V.row(v) *= radius(rng);
  return mesh;
}

Mesh moved(Mesh mesh, const Eigen::Isometry3d& place) {
  for (int v = 0; v < mesh.vertex_count(); ++v) mesh.V.row(v) = (place * Vector3d(mesh.V.row(v).transpose())).transpose();
  return mesh;
}

TEST(RayParity, MatchesWindingNumbersOnClosedMeshes) {
  std::mt19937 rng(11);
  std::normal_distribution<double> normal(0, 1);
  int inside = 0, outside = 0, unsure = 0;
  for (int trial = 0; trial < 12; ++trial) {
    Eigen::Isometry3d place = Eigen::Isometry3d::Identity();
    place.linear() = Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized().toRotationMatrix();
    place.translation() = Vector3d(normal(rng), normal(rng), normal(rng));
    const Mesh rest = trial % 3 == 0 ? make_box({1, 0.4, 0.7}) : (trial % 3 == 1 ? make_cylinder(0.4, 1, 12) : lumpy_sphere(rng));
    const Mesh mesh = moved(rest, place);
    const TriangleBvh tree(mesh.V, mesh.F);
    const Eigen::AlignedBox3d box = tree.bounds();
    std::uniform_real_distribution<double> x(box.min().x(), box.max().x()), y(box.min().y(), box.max().y()),
        z(box.min().z(), box.max().z());
    for (int n = 0; n < 300; ++n) {
      // Points in the box, and some on the mesh's own corners and edges (where rays graze).
      Vector3d q(x(rng), y(rng), z(rng));
      if (n % 10 == 0) q = mesh.V.row(static_cast<int>(rng() % mesh.vertex_count())).transpose();
      const RayParity parity = axis_ray_parity(tree, q);
      if (parity == RayParity::kUnsure) {
        ++unsure;
        continue;
      }
      const bool in = winding_number(mesh, q) >= 0.5;
      ASSERT_EQ(parity == RayParity::kOdd, in) << "trial " << trial << ", point " << n;
      ++(in ? inside : outside);
    }
  }
  EXPECT_GT(inside, 500);   // the test is not vacuous
  EXPECT_GT(outside, 500);
  EXPECT_LT(unsure, 600);   // the corners picked above, mostly
}

TEST(RayParity, GrazingRaysAndPointsOnTheSurfaceAreUnsure) {
  // A unit box's faces are split along a diagonal: from (0.5, 0.5, 0.2) the shortest way out
  // is down (−z), through the bottom face's diagonal.
  Mesh box = make_box({1, 1, 1});
  box.V.rowwise() += Eigen::RowVector3d(0.5, 0.5, 0.5);
  const TriangleBvh tree(box.V, box.F);
  EXPECT_NE(axis_ray_parity(tree, {0.5, 0.5, 0.2}), RayParity::kEven);
  EXPECT_EQ(axis_ray_parity(tree, {0.3, 0.6, 0.0}), RayParity::kUnsure);  // on the bottom face
  EXPECT_EQ(axis_ray_parity(tree, {0.3, 0.6, 0.2}), RayParity::kOdd);
  EXPECT_EQ(axis_ray_parity(tree, {0.3, 0.6, 1.5}), RayParity::kEven);  // beyond the box
}

}  // namespace
}  // namespace reconfig::geometry
