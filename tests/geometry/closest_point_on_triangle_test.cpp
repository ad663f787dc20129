#include "reconfig/geometry/closest_point_on_triangle.h"

#include <gtest/gtest.h>

#include <random>

namespace reconfig::geometry {
namespace {

/// Slow reference: the nearest of a dense barycentric grid over the triangle.
double sampled_distance(const Eigen::Vector3d& q, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                        const Eigen::Vector3d& c, int n = 400) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const Eigen::Vector3d p = a + (b - a) * (double(i) / n) + (c - a) * (double(j) / n);
      best = std::min(best, (p - q).norm());
    }
  return best;
}

TEST(ClosestPointOnTriangle, MatchesDenseSamplingOnRandomTriangles) {
  std::mt19937 random(7);
  std::normal_distribution<double> normal(0, 1);
  const auto point = [&] { return Eigen::Vector3d(normal(random), normal(random), normal(random)); };
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Vector3d a = point(), b = point(), c = point(), q = 2 * point();
    const TriangleClosestPoint found = closest_point_on_triangle(q, a, b, c);
    const double reference = sampled_distance(q, a, b, c);
    // The grid's spacing bounds how far its best sample is from the true nearest point.
    const double spacing = std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()}) / 400;
    EXPECT_LE((found.point - q).norm(), reference + 1e-12) << trial;
    EXPECT_GE((found.point - q).norm(), reference - spacing) << trial;
  }
}

TEST(ClosestPointOnTriangle, NamesTheFeature) {
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_EQ(closest_point_on_triangle({0.2, 0.2, 1}, a, b, c).feature, TriangleFeature::kFace);
  EXPECT_EQ(closest_point_on_triangle({-1, -1, 0}, a, b, c).feature, TriangleFeature::kVertex0);
  EXPECT_EQ(closest_point_on_triangle({2, -0.1, 0}, a, b, c).feature, TriangleFeature::kVertex1);
  EXPECT_EQ(closest_point_on_triangle({-0.1, 2, 0}, a, b, c).feature, TriangleFeature::kVertex2);
  EXPECT_EQ(closest_point_on_triangle({0.5, -1, 0}, a, b, c).feature, TriangleFeature::kEdge01);
  EXPECT_EQ(closest_point_on_triangle({1, 1, 0}, a, b, c).feature, TriangleFeature::kEdge12);
  EXPECT_EQ(closest_point_on_triangle({-1, 0.5, 0}, a, b, c).feature, TriangleFeature::kEdge20);
  const TriangleClosestPoint on_face = closest_point_on_triangle({0.25, 0.25, -3}, a, b, c);
  EXPECT_TRUE(on_face.point.isApprox(Eigen::Vector3d(0.25, 0.25, 0)));
}

TEST(ClosestPointOnTriangle, DegenerateTrianglesGiveTheirSegment) {
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(2, 0, 0);  // collinear
  const TriangleClosestPoint p = closest_point_on_triangle({1.5, 1, 0}, a, b, c);
  EXPECT_NEAR((p.point - Eigen::Vector3d(1.5, 0, 0)).norm(), 0, 1e-12);
  const TriangleClosestPoint point = closest_point_on_triangle({1, 1, 1}, a, a, a);
  EXPECT_EQ(point.point, a);
}

}  // namespace
}  // namespace reconfig::geometry
