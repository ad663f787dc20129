#include "sweep/detail/part_distance.h"

#include <gtest/gtest.h>

#include <random>

#include "reconfig/geometry/closest_point_on_triangle.h"
#include "reconfig/geometry/point_in_solid.h"
#include "reconfig/scene/part.h"

namespace reconfig::sweep::detail {
namespace {

/// The slow reference: the distance to every triangle, the side from the winding number.
double reference_distance(const geometry::Mesh& mesh, const Eigen::Vector3d& q) {
  double best = std::numeric_limits<double>::infinity();
  for (int f = 0; f < mesh.face_count(); ++f) {
    const Eigen::Vector3d p = geometry::closest_point_on_triangle(q, mesh.V.row(mesh.F(f, 0)), mesh.V.row(mesh.F(f, 1)),
                                                                  mesh.V.row(mesh.F(f, 2))).point;
    best = std::min(best, (p - q).norm());
  }
  return geometry::point_in_solid(mesh, q) ? -best : best;
}

TEST(PartDistance, MatchesBruteForceDistanceAndWindingNumberAtGridPoints) {
  const double h = 0.02, band = 0.1, inner = 0.05;
  for (const scene::PartSource& source : {scene::PartSource{scene::CylinderPrimitive{0.3, 0.5}},
                                          scene::PartSource{scene::SpherePrimitive{0.35}},
                                          scene::PartSource{scene::BoxPrimitive{{0.5, 0.3, 0.2}}}}) {
    geometry::Mesh mesh = scene::Part::primitive_mesh(source);
    // Turned off the grid's axes, so that rows cross edges and vertices at general positions.
    mesh.V = (mesh.V * Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix()).eval();
    const PartDistance distance(mesh, h, band, inner);
    std::mt19937 random(3);
    std::uniform_int_distribution<int> coordinate(-20, 20);
    int inside = 0, outside = 0;
    for (int n = 0; n < 1500; ++n) {
      const Eigen::Vector3d index(coordinate(random), coordinate(random), coordinate(random));
      const double expected = std::clamp(reference_distance(mesh, index * h), -inner, band);
      const double value = distance.nearest(index + Eigen::Vector3d::Constant(0.3));  // rounds to `index`
      if (expected >= band) EXPECT_GE(value, band - 1e-6) << index.transpose();
      else EXPECT_NEAR(value, expected, 1e-6) << index.transpose();
      inside += expected < 0;
      outside += expected > 0;
    }
    EXPECT_GT(inside, 50);
    EXPECT_GT(outside, 50);
  }
}

TEST(PartDistance, BeyondTheGridIsALowerBoundFromTheBoundingBall) {
  const geometry::Mesh mesh = scene::Part::primitive_mesh(scene::SpherePrimitive{0.5});
  const PartDistance distance(mesh, 0.05, 0.1, 0.1);
  const double value = distance.nearest(Eigen::Vector3d(100, 0, 0));  // 5 m away
  EXPECT_LE(value, 5.0 - 0.5 + 1e-6);
  EXPECT_GE(value, 5.0 - 0.5 - 0.06);
}

/// D(x) = max(φ(x), 0) by brute force, against the trilinear lower bound at random points
/// (off the grid): never above, and close on the box's flat walls.
TEST(PartDistance, LowerBoundNeverExceedsTheDistanceAndIsTightOnWalls) {
  const double h = 0.02;
  geometry::Mesh mesh = scene::Part::primitive_mesh(scene::BoxPrimitive{{0.5, 0.3, 0.2}});
  const PartDistance distance(mesh, h, 0.12, 0.05);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> coordinate(-0.4, 0.4);
  int near_wall = 0;
  for (int n = 0; n < 3000; ++n) {
    const Eigen::Vector3d x(coordinate(random), coordinate(random), coordinate(random));
    const double exact = std::max(0.0, reference_distance(mesh, x));
    const double bound = distance.lower_bound(x / h);
    EXPECT_LE(bound, exact) << x.transpose();
    EXPECT_GE(bound, 0.0);
    // In front of a face (not near an edge) and inside the band: within h²/(2 D) of D.
    const Eigen::Vector3d excess = (x.cwiseAbs() - Eigen::Vector3d(0.25, 0.15, 0.1)).cwiseMax(0.0);
    if (exact > 0.02 && exact < 0.1 && (excess.array() > 0).count() == 1) {
      EXPECT_GE(bound, exact - h * h / (2 * exact) - 1e-9) << x.transpose();
      ++near_wall;
    }
  }
  EXPECT_GT(near_wall, 100);
}

}  // namespace
}  // namespace reconfig::sweep::detail
