#include "reconfig/geometry/signed_distance.h"

#include <gtest/gtest.h>

#include <random>

#include "reconfig/geometry/closest_point_on_triangle.h"
#include "reconfig/geometry/point_in_solid.h"
#include "reconfig/geometry/primitives.h"

namespace reconfig::geometry {
namespace {

double brute_force_distance(const Mesh& mesh, const Eigen::Vector3d& q) {
  double best = std::numeric_limits<double>::infinity();
  for (int f = 0; f < mesh.face_count(); ++f) {
    const Eigen::Vector3d p = closest_point_on_triangle(q, mesh.V.row(mesh.F(f, 0)).transpose(),
                                                        mesh.V.row(mesh.F(f, 1)).transpose(),
                                                        mesh.V.row(mesh.F(f, 2)).transpose())
                                  .point;
    best = std::min(best, (p - q).norm());
  }
  return best;
}

/// Closed meshes whose corners, edges and faces all matter for the sign.
std::vector<Mesh> test_meshes() {
  Mesh two_boxes = make_box({1, 1, 1});
  const Mesh other = make_box({0.4, 2, 0.4});
  const int n = two_boxes.vertex_count();
  two_boxes.V.conservativeResize(n + other.vertex_count(), 3);
  two_boxes.V.bottomRows(other.vertex_count()) = other.V.rowwise() + Eigen::RowVector3d(2, 0, 0);
  two_boxes.F.conservativeResize(two_boxes.face_count() + other.face_count(), 3);
  two_boxes.F.bottomRows(other.face_count()) = other.F.array() + n;
  return {make_box({1, 0.5, 2}), make_sphere(0.7, 2), make_cylinder(0.3, 1.2, 10), two_boxes};
}

TEST(MeshSignedDistance, SignMatchesWindingNumbersAndDistanceMatchesBruteForce) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-0.2, 1.2);
  int inside = 0, outside = 0;
  for (const Mesh& mesh : test_meshes()) {
    const MeshSignedDistance sdf(mesh);
    const Eigen::Vector3d lo = mesh.V.colwise().minCoeff(), size = mesh.V.colwise().maxCoeff().transpose() - lo;
    for (int i = 0; i < 400; ++i) {  // points in the mesh's box widened by a fifth on each side
      const Eigen::Vector3d q = lo + Eigen::Vector3d(unit(random), unit(random), unit(random)).cwiseProduct(size);
      const MeshSignedDistance::Query d = sdf.query(q);
      ASSERT_GE(d.triangle, 0);
      EXPECT_NEAR(std::abs(d.distance), brute_force_distance(mesh, q), 1e-12) << q.transpose();
      EXPECT_EQ(d.distance < 0, point_in_solid(mesh, q)) << q.transpose();
      (d.distance < 0 ? inside : outside) += 1;
    }
  }
  EXPECT_GT(inside, 100);  // both sides were exercised
  EXPECT_GT(outside, 100);
}

TEST(MeshSignedDistance, PointsNearestToCornersAndEdgesGetTheRightSign) {
  const Mesh box = make_box({2, 2, 2});
  const MeshSignedDistance sdf(box);
  EXPECT_GT(sdf.query({1.1, 1.1, 1.1}).distance, 0);   // beyond a corner
  EXPECT_GT(sdf.query({1.1, 1.1, 0.0}).distance, 0);   // beyond an edge
  EXPECT_LT(sdf.query({0.95, 0.95, 0.95}).distance, 0);
  EXPECT_NEAR(sdf.query({0.0, 0.0, 0.0}).distance, -1.0, 1e-12);
  EXPECT_NEAR(sdf.query({3.0, 0.0, 0.0}).distance, 2.0, 1e-12);
}

TEST(MeshSignedDistance, MaxDistanceLimitsTheSearch) {
  const MeshSignedDistance sdf(make_box({1, 1, 1}));
  EXPECT_EQ(sdf.query({5, 0, 0}, 1.0).triangle, -1);
  EXPECT_GE(sdf.query({1, 0, 0}, 1.0).triangle, 0);
}

}  // namespace
}  // namespace reconfig::geometry
