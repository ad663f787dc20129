#include "reconfig/geometry/triangle_closest_points.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace reconfig::geometry {
namespace {

/// Normally distributed vectors from one seed.
class RandomVectors {
 public:
  explicit RandomVectors(unsigned seed) : random_(seed) {}
  Eigen::Vector3d operator()() { return {normal_(random_), normal_(random_), normal_(random_)}; }

 private:
  std::mt19937 random_;
  std::normal_distribution<double> normal_;
};

TriangleCorners random_triangle(RandomVectors& random, const Eigen::Vector3d& around) {
  return {around + random(), around + random(), around + random()};
}

/// Slow reference: the least distance between points of a dense barycentric grid on each.
double sampled_distance(const TriangleCorners& a, const TriangleCorners& b, int n) {
  std::vector<Eigen::Vector3d> pa, pb;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const double u = double(i) / n, v = double(j) / n;
      pa.push_back(a[0] + u * (a[1] - a[0]) + v * (a[2] - a[0]));
      pb.push_back(b[0] + u * (b[1] - b[0]) + v * (b[2] - b[0]));
    }
  double best = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& p : pa)
    for (const Eigen::Vector3d& q : pb) best = std::min(best, (p - q).norm());
  return best;
}

/// Whether p lies in triangle t (within `eps` of its plane and inside its edges).
bool in_triangle(const Eigen::Vector3d& p, const TriangleCorners& t, double eps) {
  const Eigen::Vector3d n = (t[1] - t[0]).cross(t[2] - t[0]);
  if (std::abs(n.normalized().dot(p - t[0])) > eps) return false;
  for (int k = 0; k < 3; ++k)
    if (n.dot((t[(k + 1) % 3] - t[k]).cross(p - t[k])) < -eps * n.norm()) return false;
  return true;
}

TEST(TriangleClosestPoints, MatchesDenseSamplingOnRandomPairs) {
  RandomVectors random(3);
  for (int trial = 0; trial < 100; ++trial) {
    const TriangleCorners a = random_triangle(random, Eigen::Vector3d::Zero());
    const TriangleCorners b = random_triangle(random, 1.5 * random());
    const TriangleClosestPoints c = triangle_closest_points(a, b);
    // The sampled distance is at least the true one, and within the grid's spacing of it.
    const double sampled = sampled_distance(a, b, 30);
    double longest = 0;
    for (int k = 0; k < 3; ++k) longest = std::max({longest, (a[k] - a[(k + 1) % 3]).norm(), (b[k] - b[(k + 1) % 3]).norm()});
    EXPECT_LE(c.distance, sampled + 1e-12) << trial;
    EXPECT_GE(c.distance, sampled - 2 * longest / 30) << trial;
    EXPECT_EQ(c.distance, triangle_distance(a, b)) << trial;
    if (c.distance > 0) {
      EXPECT_NEAR((c.on_a - c.on_b).norm(), c.distance, 1e-12) << trial;
      EXPECT_TRUE(in_triangle(c.on_a, a, 1e-9)) << trial;
      EXPECT_TRUE(in_triangle(c.on_b, b, 1e-9)) << trial;
    }
    EXPECT_NEAR(triangle_closest_points(b, a).distance, c.distance, 1e-12) << trial;  // symmetric
  }
}

TEST(TriangleClosestPoints, CrossingTouchingAndDegenerateTrianglesAreDefined) {
  const TriangleCorners a = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)};
  // Piercing through the middle (no vertex or edge pair at distance 0): still 0.
  const TriangleCorners pierce = {Eigen::Vector3d(0.2, 0.2, -1), Eigen::Vector3d(0.3, 0.2, 1), Eigen::Vector3d(0.25, 3, 1)};
  EXPECT_EQ(triangle_closest_points(a, pierce).distance, 0.0);
  // Coplanar, overlapping.
  const TriangleCorners coplanar = {Eigen::Vector3d(0.1, 0.1, 0), Eigen::Vector3d(2, 0.1, 0), Eigen::Vector3d(0.1, 2, 0)};
  EXPECT_EQ(triangle_closest_points(a, coplanar).distance, 0.0);
  // A vertex 1e-7 above the face: exactly that far.
  const TriangleCorners above = {Eigen::Vector3d(0.2, 0.2, 1e-7), Eigen::Vector3d(0.2, 0.3, 1), Eigen::Vector3d(0.3, 0.2, 1)};
  EXPECT_NEAR(triangle_closest_points(a, above).distance, 1e-7, 1e-15);
  // Collapsed to a point and to a segment: finite.
  const TriangleCorners point = {Eigen::Vector3d(2, 2, 2), Eigen::Vector3d(2, 2, 2), Eigen::Vector3d(2, 2, 2)};
  const TriangleCorners segment = {Eigen::Vector3d(3, 0, 1), Eigen::Vector3d(-3, 0, 1), Eigen::Vector3d(0, 0, 1)};
  EXPECT_NEAR(triangle_closest_points(a, point).distance, (Eigen::Vector3d(2, 2, 2) - Eigen::Vector3d(0.5, 0.5, 0)).norm(), 1e-12);
  EXPECT_NEAR(triangle_closest_points(a, segment).distance, 1.0, 1e-12);
  EXPECT_NEAR(triangle_closest_points(point, segment).distance, (Eigen::Vector3d(2, 2, 2) - Eigen::Vector3d(2, 0, 1)).norm(), 1e-12);
}

}  // namespace
}  // namespace reconfig::geometry
