#include "reconfig/geometry/ray_winding.h"

#include <CGAL/Gmpq.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>

#include "mesh_test_helpers.h"
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

TEST(RayWinding, OrientationNeverContradictsTheExactOne) {
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

TEST(RayWinding, OrientationDoesNotAnswerWhereItsProductsUnderflow) {
  // Tiny coordinates: the determinant's products fall below the range where the relative bound
  // holds, whatever their sign.
  const double tiny = std::ldexp(1.0, -520);
  const Vector3d a(0, 0, 0), b(0, tiny, 0), c(0, 0, tiny);
  EXPECT_EQ(certain_orientation_2d(a, b, c, 1, 2), 0);
  EXPECT_EQ(certain_orientation_2d(a, b, c * 2e150, 1, 2), 1);  // and answers once they do not
}

/// A closed, irregular, star-shaped mesh: a sphere with every vertex moved along its ray.
Mesh lumpy_sphere(std::mt19937& rng) {
  Mesh mesh = make_sphere(0.5, 3);
  std::uniform_real_distribution<double> radius(0.6, 1.4);
  for (int v = 0; v < mesh.vertex_count(); ++v) mesh.V.row(v) *= radius(rng);
  return mesh;
}

Mesh moved(const Mesh& mesh, const Eigen::Isometry3d& place) { return testing::transformed(mesh, Eigen::Affine3d(place)); }

/// Closed, consistently oriented meshes with their shells overlapping or nested in some trials
/// (winding number 2 there), rotated and moved at random.
Mesh random_closed_mesh(std::mt19937& rng, int trial) {
  std::normal_distribution<double> normal(0, 1);
  Eigen::Isometry3d place = Eigen::Isometry3d::Identity();
  place.linear() = Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized().toRotationMatrix();
  place.translation() = Vector3d(normal(rng), normal(rng), normal(rng));
  Eigen::Isometry3d aside = Eigen::Isometry3d::Identity();
  aside.translation() = Vector3d(0.3, 0.1, 0);
  switch (trial % 5) {
    case 0: return moved(make_box({1, 0.4, 0.7}), place);
    case 1: return moved(make_cylinder(0.4, 1, 12), place);
    case 2: return moved(lumpy_sphere(rng), place);
    case 3: return moved(testing::merge(make_sphere(0.5, 3), moved(make_box({0.6, 0.6, 0.6}), aside)), place);  // overlapping
    default: return moved(testing::merge(make_sphere(0.5, 3), make_sphere(0.25, 2)), place);  // nested
  }
}

TEST(RayWinding, MatchesWindingNumbersOnClosedMeshes) {
  std::mt19937 rng(11);
  int zero = 0, one = 0, two = 0, unsure = 0;
  for (int trial = 0; trial < 15; ++trial) {
    const Mesh mesh = random_closed_mesh(rng, trial);
    const TriangleBvh tree(mesh.V, mesh.F);
    const Eigen::AlignedBox3d box = tree.bounds();
    std::uniform_real_distribution<double> x(box.min().x(), box.max().x()), y(box.min().y(), box.max().y()),
        z(box.min().z(), box.max().z());
    for (int n = 0; n < 300; ++n) {
      // Points in the box, and some on the mesh's own corners (where rays graze).
      Vector3d q(x(rng), y(rng), z(rng));
      if (n % 10 == 0) q = mesh.V.row(static_cast<int>(rng() % mesh.vertex_count())).transpose();
      const RayWinding ray = axis_ray_winding(tree, q);
      if (!ray.certain) {
        ++unsure;
        continue;
      }
      const double reference = winding_number(mesh, q);
      ASSERT_NEAR(ray.winding, reference, 1e-6) << "trial " << trial << ", point " << n;
      ++(ray.winding == 0 ? zero : (ray.winding == 1 ? one : two));
    }
  }
  EXPECT_GT(zero, 500);  // the test is not vacuous
  EXPECT_GT(one, 500);
  EXPECT_GT(two, 50);    // overlapping and nested shells count twice
  EXPECT_LT(unsure, 700);  // the corners picked above, mostly
}

TEST(RayWinding, GrazingRaysAndPointsOnTheSurfaceAreNotCertain) {
  // A unit box's faces are split along a diagonal: from (0.5, 0.5, 0.2) the shortest way out
  // is down (−z), through the bottom face's diagonal.
  Mesh box = make_box({1, 1, 1});
  box.V.rowwise() += Eigen::RowVector3d(0.5, 0.5, 0.5);
  const TriangleBvh tree(box.V, box.F);
  EXPECT_FALSE(axis_ray_winding(tree, {0.5, 0.5, 0.2}).certain);
  EXPECT_FALSE(axis_ray_winding(tree, {0.3, 0.6, 0.0}).certain);  // on the bottom face
  const RayWinding inside = axis_ray_winding(tree, {0.3, 0.6, 0.2});
  EXPECT_TRUE(inside.certain);
  EXPECT_EQ(inside.winding, 1);
  const RayWinding beyond = axis_ray_winding(tree, {0.3, 0.6, 1.5});
  EXPECT_TRUE(beyond.certain);
  EXPECT_EQ(beyond.winding, 0);
  // Turned inside out, the box winds the other way.
  Mesh inverted = box;
  inverted.F.col(1).swap(inverted.F.col(2));
  const RayWinding inward = axis_ray_winding(TriangleBvh(inverted.V, inverted.F), {0.3, 0.6, 0.2});
  EXPECT_TRUE(inward.certain);
  EXPECT_EQ(inward.winding, -1);
}

}  // namespace
}  // namespace reconfig::geometry
