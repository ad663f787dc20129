#include "sweep/detail/clearance_check.h"

#include <gtest/gtest.h>

#include <random>

#include "reconfig/scene/part.h"

namespace reconfig::sweep::detail {
namespace {

/// The distance from x to a finite point set, by brute force.
double distance_to(const std::vector<Eigen::Vector3d>& set, const Eigen::Vector3d& x) {
  double best = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& s : set) best = std::min(best, (x - s).norm());
  return best;
}

/// Random point sets and triangles: the bound from exact corner distances is never above the
/// squared distance at dense points of the triangle, and it equals it for a single point.
TEST(ClearanceCheck, SquaredDistanceBoundIsBelowDenseSamplesOfTheTriangle) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  const auto point = [&] { return Eigen::Vector3d(coordinate(random), coordinate(random), coordinate(random)); };
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Eigen::Vector3d> set(std::size_t(1 + trial % 5));
    for (Eigen::Vector3d& s : set) s = point() * 0.5;
    const Eigen::Vector3d v[3] = {point(), point(), point()};
    const double L2[3] = {std::pow(distance_to(set, v[0]), 2), std::pow(distance_to(set, v[1]), 2),
                          std::pow(distance_to(set, v[2]), 2)};
    const double bound = squared_distance_lower_bound(v, L2);
    double dense = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= 40; ++i)
      for (int j = 0; i + j <= 40; ++j) {
        const Eigen::Vector3d q = v[0] + (v[1] - v[0]) * (i / 40.0) + (v[2] - v[0]) * (j / 40.0);
        dense = std::min(dense, std::pow(distance_to(set, q), 2));
      }
    EXPECT_LE(bound, dense + 1e-12) << trial;
    if (set.size() == 1) {  // d² is then |x − s|² itself: the bound is exact
      EXPECT_NEAR(bound, dense, 2e-3) << trial;
    }
  }
}

TEST(ClearanceCheck, SeesAMeshThatCutsIntoTheSetAndPassesOneThatDoesNot) {
  const geometry::Mesh cube = scene::Part::primitive_mesh(scene::BoxPrimitive{{1, 1, 1}});
  // S: a ball of radius 0.3 at the origin; the cube's faces lie 0.5 from its center.
  const DistanceLowerBound ball = [](const Eigen::Vector3d& x) { return std::max(0.0, x.norm() - 0.3); };
  // Its 12 big triangles need splitting (the bound loses the triangle's spread).
  EXPECT_FALSE(mesh_keeps_clear(cube, std::nullopt, 0.19, ball, 0));
  EXPECT_TRUE(mesh_keeps_clear(cube, std::nullopt, 0.19, ball, 5));
  EXPECT_FALSE(mesh_keeps_clear(cube, std::nullopt, 0.21, ball, 5));
  // Only the region matters: a box far from the cube asks for nothing.
  EXPECT_TRUE(mesh_keeps_clear(cube, Eigen::AlignedBox3d(Eigen::Vector3d::Constant(5), Eigen::Vector3d::Constant(6)),
                               0.21, ball, 5));
}

}  // namespace
}  // namespace reconfig::sweep::detail
