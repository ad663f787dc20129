#include "reconfig/geometry/point_in_solid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <utility>

#include "exact_kernels_test_util.h"

namespace reconfig::geometry {
namespace {

using Eigen::Vector3d;

/// Every edge used by exactly two faces, in opposite directions.
bool closed_and_oriented(const Mesh& mesh) {
  std::map<std::pair<int, int>, int> directed;
  for (int f = 0; f < mesh.face_count(); ++f)
    for (int c = 0; c < 3; ++c) ++directed[{mesh.F(f, c), mesh.F(f, (c + 1) % 3)}];
  for (const auto& [edge, count] : directed) {
    if (count != 1) return false;
    const auto twin = directed.find({edge.second, edge.first});
    if (twin == directed.end() || twin->second != 1) return false;
  }
  return true;
}

/// Ray-casting parity along `dir` (Möller–Trumbore); returns -1 if the ray passes too close to
/// an edge or vertex to trust doubles, so the caller picks another direction.
int ray_parity(const Mesh& mesh, const Vector3d& q, const Vector3d& dir) {
  int hits = 0;
  for (int f = 0; f < mesh.face_count(); ++f) {
    const Vector3d a = mesh.V.row(mesh.F(f, 0)).transpose(), b = mesh.V.row(mesh.F(f, 1)).transpose(),
                   c = mesh.V.row(mesh.F(f, 2)).transpose();
    const Vector3d e1 = b - a, e2 = c - a, p = dir.cross(e2);
    const double det = e1.dot(p);
    const double scale = e1.norm() * e2.norm();
    if (std::abs(det) < 1e-12 * scale) continue;  // ray parallel to the face plane
    const Vector3d s = q - a;
    const double u = s.dot(p) / det;
    const Vector3d r = s.cross(e1);
    const double v = dir.dot(r) / det, t = e2.dot(r) / det;
    const double margin = 1e-7;
    const bool clear = std::min({std::abs(u), std::abs(v), std::abs(1 - u - v)}) > margin;
    if (u >= -margin && v >= -margin && u + v <= 1 + margin && t > -margin) {
      if (!clear || std::abs(t) < margin) return -1;
      ++hits;
    }
  }
  return hits % 2;
}

void expect_matches_ray_parity(const Mesh& mesh, int queries, unsigned seed) {
  ASSERT_TRUE(closed_and_oriented(mesh));
  Eigen::AlignedBox3d box;
  for (int v = 0; v < mesh.vertex_count(); ++v) box.extend(Vector3d(mesh.V.row(v).transpose()));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal;
  int inside = 0;
  for (int i = 0; i < queries; ++i) {
    // Points in the box grown by 10%, and points near the surface (both sides).
    const Vector3d t(unit(rng), unit(rng), unit(rng));
    Vector3d q = box.min() - 0.1 * box.sizes() + t.cwiseProduct(1.2 * box.sizes());
    if (i % 2) {
      std::uniform_int_distribution<int> vertex(0, mesh.vertex_count() - 1);
      q = mesh.V.row(vertex(rng)).transpose() +
          0.02 * box.diagonal().norm() * Vector3d(normal(rng), normal(rng), normal(rng));
    }
    int parity = -1;
    while (parity < 0) parity = ray_parity(mesh, q, Vector3d(normal(rng), normal(rng), normal(rng)).normalized());
    const double w = winding_number(mesh, q);
    EXPECT_NEAR(w, parity, 1e-6) << "query " << q.transpose();
    EXPECT_EQ(point_in_solid(mesh, q), parity == 1) << "query " << q.transpose();
    inside += parity;
  }
  EXPECT_GT(inside, queries / 10);
  EXPECT_LT(inside, queries * 19 / 20);
}

TEST(PointInSolid, MatchesRayParityOnCube) { expect_matches_ray_parity(testing::cgal_off("cube.off"), 200, 1); }

TEST(PointInSolid, MatchesRayParityOnElephant) {
  expect_matches_ray_parity(testing::cgal_off("elephant.off"), 60, 2);
}

TEST(PointInSolid, SolidAngleOfOctantTriangle) {
  // The triangle with corners on the three axes covers one octant of the unit sphere seen
  // from the origin: |w| = 1/8, positive when its normal points away from the query.
  Mesh mesh;
  mesh.V.resize(3, 3);
  mesh.V << 1, 0, 0, 0, 1, 0, 0, 0, 1;
  mesh.F.resize(1, 3);
  mesh.F << 0, 1, 2;
  EXPECT_NEAR(winding_number(mesh, Vector3d::Zero()), 1.0 / 8, 1e-14);
  mesh.F << 0, 2, 1;
  EXPECT_NEAR(winding_number(mesh, Vector3d::Zero()), -1.0 / 8, 1e-14);
  // Far in the plane's extension the solid angle vanishes.
  EXPECT_NEAR(winding_number(mesh, Vector3d(1e6, 1e6, -2e6 + 1)), 0.0, 1e-9);
}

TEST(PointInSolid, OpenCubeGivesFractionalWinding) {
  // Each face of a cube subtends 1/6 of the sphere from its center.
  Mesh cube = testing::cgal_off("cube.off");
  ASSERT_EQ(cube.face_count(), 12);
  Vector3d center = cube.V.colwise().mean().transpose();
  EXPECT_NEAR(winding_number(cube, center), 1.0, 1e-12);
  Mesh open = cube;
  open.F = cube.F.topRows(10);  // two triangles less: one face of the cube removed, if paired
  const double w = winding_number(open, center);
  // Whatever two triangles were removed, they subtend between 0 and 2/6 of the sphere.
  EXPECT_GT(w, 4.0 / 6 - 1e-12);
  EXPECT_LT(w, 1.0 - 1e-3);
  // Flipping every face flips the sign; point_in_solid still says inside.
  Mesh flipped = cube;
  flipped.F.col(1).swap(flipped.F.col(2));
  EXPECT_NEAR(winding_number(flipped, center), -1.0, 1e-12);
  EXPECT_TRUE(point_in_solid(flipped, center));
}

TEST(PointInSolid, LargeMeshUsesDeterministicParallelSum) {
  // Many copies of the cube side by side (> the parallel threshold): the sum is identical
  // between calls and equals the count of cubes containing the point.
  const Mesh cube = testing::cgal_off("cube.off");
  const int copies = 2000;
  Mesh many;
  many.V.resize(cube.vertex_count() * copies, 3);
  many.F.resize(cube.face_count() * copies, 3);
  for (int k = 0; k < copies; ++k) {
    many.V.middleRows(k * cube.vertex_count(), cube.vertex_count()) = cube.V;
    many.V.middleRows(k * cube.vertex_count(), cube.vertex_count()).col(0).array() += 3.0 * (k % 2);
    many.F.middleRows(k * cube.face_count(), cube.face_count()) = cube.F.array() + k * cube.vertex_count();
  }
  const Vector3d center = cube.V.colwise().mean().transpose();
  const double w1 = winding_number(many, center), w2 = winding_number(many, center);
  EXPECT_EQ(w1, w2);
  EXPECT_NEAR(w1, copies / 2, 1e-9);
}

}  // namespace
}  // namespace reconfig::geometry
