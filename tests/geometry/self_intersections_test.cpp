#include "reconfig/geometry/self_intersections.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "exact_kernels_test_util.h"
#include "mesh_test_helpers.h"
#include "reconfig/common/input_error.h"
#include "reconfig/geometry/triangle_bvh.h"
#include "reconfig/geometry/triangle_intersection.h"

namespace reconfig::geometry {
namespace {

using Eigen::Vector3d;
using testing::merge;
using Pairs = std::vector<std::pair<int, int>>;

Vector3d corner(const Mesh& mesh, int f, int c) { return mesh.V.row(mesh.F(f, c)).transpose(); }

/// Reference for one pair, by a different route than the library: construct what the closed
/// triangles share (exact construction, rounded) and look for an extreme point of it outside
/// the hull of the shared vertices (the shared set is convex, so if all its extreme points lie
/// in the shared vertex/edge, all of it does). Duplicate faces share their interior.
bool reference_improper(const Mesh& mesh, int f, int g) {
  std::vector<int> shared;
  for (int c = 0; c < 3; ++c)
    for (int d = 0; d < 3; ++d)
      if (mesh.F(f, c) == mesh.F(g, d) && std::find(shared.begin(), shared.end(), mesh.F(f, c)) == shared.end())
        shared.push_back(mesh.F(f, c));
  const Vector3d a0 = corner(mesh, f, 0), a1 = corner(mesh, f, 1), a2 = corner(mesh, f, 2);
  if (shared.size() == 3) return (a1 - a0).cross(a2 - a0).squaredNorm() > 0;
  const TriangleContact contact = intersect_triangles(a0, a1, a2, corner(mesh, g, 0), corner(mesh, g, 1), corner(mesh, g, 2));
  if (!contact.intersect) return false;
  if (shared.empty()) return true;
  const Vector3d u = mesh.V.row(shared.front()).transpose(), v = mesh.V.row(shared.back()).transpose();
  return std::any_of(contact.points.begin(), contact.points.end(),
                     [&](const Vector3d& p) { return reconfig::testing::distance_to_segment(p, u, v) > 1e-9; });
}

Pairs brute_force(const Mesh& mesh) {
  Pairs pairs;
  for (int f = 0; f < mesh.face_count(); ++f)
    for (int g = f + 1; g < mesh.face_count(); ++g)
      if (reference_improper(mesh, f, g)) pairs.emplace_back(f, g);
  return pairs;
}

Mesh transformed(const Mesh& mesh, const Eigen::Matrix3d& R, const Vector3d& t) {
  Eigen::Affine3d T = Eigen::Affine3d::Identity();
  T.linear() = R;
  T.translation() = t;
  return testing::transformed(mesh, T);
}

TEST(SelfIntersections, MatchesReferenceOnRandomGridMeshes) {
  // Small integer-grid "meshes" whose faces share vertices and edges in every possible way,
  // including coplanar folds, repeated indices, zero-area faces and coincident vertices.
  std::mt19937 rng(2024);
  std::uniform_int_distribution<int> coord(-2, 2);
  int improper = 0, adjacent_improper = 0, total = 0;
  for (int trial = 0; trial < 30; ++trial) {
    Mesh mesh;
    const int nv = 6 + trial % 7, nf = 10 + trial % 20;
    mesh.V.resize(nv, 3);
    for (int v = 0; v < nv; ++v) mesh.V.row(v) = Vector3d(coord(rng), coord(rng), trial % 3 == 0 ? 0 : coord(rng));
    std::uniform_int_distribution<int> vertex(0, nv - 1);
    mesh.F.resize(nf, 3);
    for (int f = 0; f < nf; ++f) {
      mesh.F.row(f) = Eigen::RowVector3i(vertex(rng), vertex(rng), vertex(rng));
      if (trial % 4 != 1)  // mostly faces with three distinct indices
        while (mesh.F(f, 1) == mesh.F(f, 0) || mesh.F(f, 2) == mesh.F(f, 0) || mesh.F(f, 2) == mesh.F(f, 1))
          mesh.F.row(f) = Eigen::RowVector3i(vertex(rng), vertex(rng), vertex(rng));
    }
    const Pairs expected = brute_force(mesh);
    const SelfIntersections found = find_self_intersections(mesh, 100000);
    ASSERT_EQ(found.pairs, expected) << "trial " << trial << "\nV\n" << mesh.V << "\nF\n" << mesh.F;
    EXPECT_FALSE(found.truncated);
    for (int f = 0; f < nf; ++f)
      for (int g = 0; g < nf; ++g) {
        const bool pair_improper = faces_intersect_improperly(mesh, f, g);
        ASSERT_EQ(pair_improper, faces_intersect_improperly(mesh, g, f));
        if (f < g) {
          total += 1;
          improper += pair_improper;
          const bool adjacent = (mesh.F.row(f).array() == mesh.F(g, 0)).any() ||
                                (mesh.F.row(f).array() == mesh.F(g, 1)).any() ||
                                (mesh.F.row(f).array() == mesh.F(g, 2)).any();
          adjacent_improper += pair_improper && adjacent;
        }
      }
  }
  EXPECT_GT(improper, total / 10);
  EXPECT_GT(adjacent_improper, 40);  // the shared-vertex/edge rules are exercised
}

TEST(SelfIntersections, FoldedAdjacentFaces) {
  // A unit square split along its diagonal 0–2; faces (0,1,2) and (0,2,3).
  Mesh mesh;
  mesh.V.resize(4, 3);
  mesh.V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  mesh.F.resize(2, 3);
  mesh.F << 0, 1, 2, 0, 2, 3;
  EXPECT_TRUE(find_self_intersections(mesh).pairs.empty());  // flat
  mesh.V.row(3) << 0, 1, 1;                                   // bent along the diagonal
  EXPECT_TRUE(find_self_intersections(mesh).pairs.empty());
  mesh.V.row(3) << 1, 0.2, 0;  // folded flat onto face 0
  EXPECT_EQ(find_self_intersections(mesh).pairs, (Pairs{{0, 1}}));
  mesh.V.row(3) << 1, 0.2, 1e-15;  // almost folded: the faces only share their edge
  EXPECT_TRUE(find_self_intersections(mesh).pairs.empty());
  // Sharing one vertex only: face (0,4,5) dips through face (0,1,2) away from vertex 0.
  mesh.V.conservativeResize(6, 3);
  mesh.V.row(3) << 0, 1, 0;
  mesh.V.row(4) << 0.9, 0.5, -1;
  mesh.V.row(5) << 0.9, 0.5, 1;
  mesh.F.conservativeResize(3, 3);
  mesh.F.row(2) << 0, 4, 5;
  EXPECT_EQ(find_self_intersections(mesh).pairs, (Pairs{{0, 2}}));
  mesh.V.row(4) << 2, 2, -1;  // now it contains the diagonal edge 0–2 of both faces 0 and 1
  mesh.V.row(5) << 2, 2, 1;
  EXPECT_EQ(find_self_intersections(mesh).pairs, (Pairs{{0, 2}, {1, 2}}));
  mesh.V.row(4) << 2, -2, -1;  // only vertex 0 in common
  mesh.V.row(5) << 2, -2, 1;
  EXPECT_TRUE(find_self_intersections(mesh).pairs.empty());
}

TEST(SelfIntersections, CleanClosedMeshesHaveNone) {
  for (const char* name : {"cube.off", "elephant.off"}) {
    const Mesh mesh = reconfig::testing::cgal_off(name);
    const SelfIntersections found = find_self_intersections(mesh);
    EXPECT_TRUE(found.pairs.empty()) << name << ": " << found.pairs.size() << " pairs";
    EXPECT_FALSE(found.truncated);
    EXPECT_FALSE(find_self_intersections(mesh, 0).truncated);
  }
}

TEST(SelfIntersections, InterpenetratingCopiesOfCube) {
  const Mesh cube = reconfig::testing::cgal_off("cube.off");
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.4, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  for (const Mesh& other : {transformed(cube, Eigen::Matrix3d::Identity(), Vector3d(0.5, 0.5, 0.5)),
                            transformed(cube, R, Vector3d(0.3, -0.2, 0.1)),
                            transformed(cube, Eigen::Matrix3d::Identity(), Vector3d(2, 0, 0)),    // touching face
                            transformed(cube, Eigen::Matrix3d::Identity(), Vector3d(2.5, 0, 0))}) {  // apart
    const Mesh merged = merge(cube, other);
    const Pairs expected = brute_force(merged);
    EXPECT_EQ(find_self_intersections(merged).pairs, expected);
    for (auto [f, g] : expected) {  // only pairs across the copies
      EXPECT_LT(f, cube.face_count());
      EXPECT_GE(g, cube.face_count());
    }
  }
  EXPECT_FALSE(brute_force(merge(cube, transformed(cube, Eigen::Matrix3d::Identity(), Vector3d(0.5, 0.5, 0.5)))).empty());
  EXPECT_FALSE(brute_force(merge(cube, transformed(cube, Eigen::Matrix3d::Identity(), Vector3d(2, 0, 0)))).empty());
  EXPECT_TRUE(brute_force(merge(cube, transformed(cube, Eigen::Matrix3d::Identity(), Vector3d(2.5, 0, 0)))).empty());
}

TEST(SelfIntersections, InterpenetratingCopiesOfElephant) {
  // Two posed copies of a clean mesh: the improper pairs are exactly the intersecting pairs
  // across the copies, found here independently with two trees and a dual traversal.
  const Mesh elephant = reconfig::testing::cgal_off("elephant.off");
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Vector3d(0, 1, 0)).toRotationMatrix();
  const Mesh other = transformed(elephant, R, Vector3d(0.05, 0.02, 0));
  const Mesh merged = merge(elephant, other);
  Pairs expected;
  const TriangleBvh ta(elephant.V, elephant.F), tb(other.V, other.F);
  ta.for_each_overlapping_pair(tb, [&](int f, int g) {
    if (triangles_intersect(corner(elephant, f, 0), corner(elephant, f, 1), corner(elephant, f, 2), corner(other, g, 0),
                            corner(other, g, 1), corner(other, g, 2)))
      expected.emplace_back(f, g + elephant.face_count());
  });
  std::sort(expected.begin(), expected.end());
  ASSERT_GT(expected.size(), 20u);
  const SelfIntersections all = find_self_intersections(merged, 1000000);
  EXPECT_EQ(all.pairs, expected);
  EXPECT_FALSE(all.truncated);

  // Truncation keeps the lexicographically smallest pairs.
  const SelfIntersections first = find_self_intersections(merged, 7);
  EXPECT_TRUE(first.truncated);
  EXPECT_EQ(first.pairs, Pairs(expected.begin(), expected.begin() + 7));
  const SelfIntersections none = find_self_intersections(merged, 0);
  EXPECT_TRUE(none.truncated);
  EXPECT_TRUE(none.pairs.empty());

  // Progress reaches 1 in increasing steps; cancelling stops early.
  std::vector<double> steps;
  find_self_intersections(merged, 1000000, [&](double x) {
    steps.push_back(x);
    return true;
  });
  ASSERT_FALSE(steps.empty());
  EXPECT_TRUE(std::is_sorted(steps.begin(), steps.end()));
  EXPECT_EQ(steps.back(), 1.0);
  const SelfIntersections cancelled = find_self_intersections(merged, 1000000, [](double) { return false; });
  EXPECT_TRUE(cancelled.cancelled);
}

TEST(SelfIntersections, FaceFoldedThroughAnother) {
  // Pull one corner of the cube through the opposite side: the faces around it pierce
  // faces they do not share a vertex with.
  Mesh cube = reconfig::testing::cgal_off("cube.off");
  const Vector3d center = cube.V.colwise().mean().transpose();
  const Vector3d v0 = cube.V.row(0).transpose();
  cube.V.row(0) = (center + 1.6 * (center - v0)).transpose();
  const Pairs expected = brute_force(cube);
  ASSERT_FALSE(expected.empty());
  EXPECT_EQ(find_self_intersections(cube).pairs, expected);
  for (auto [f, g] : expected) EXPECT_TRUE((cube.F.row(f).array() == 0).any() || (cube.F.row(g).array() == 0).any());
}

TEST(SelfIntersections, DuplicateAndDegenerateFaces) {
  Mesh mesh;
  mesh.V.resize(4, 3);
  mesh.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0;
  mesh.F.resize(2, 3);
  mesh.F << 0, 1, 2, 2, 1, 0;  // the same face twice, flipped
  EXPECT_EQ(find_self_intersections(mesh).pairs, (Pairs{{0, 1}}));
  mesh.F << 0, 1, 3, 3, 1, 0;  // a zero-area face twice: it is all edges
  EXPECT_TRUE(find_self_intersections(mesh).pairs.empty());
  mesh.F << 0, 1, 2, 0, 3, 3;  // segment 0–3 (repeated index) along edge 0–1 of face 0
  EXPECT_EQ(find_self_intersections(mesh).pairs, (Pairs{{0, 1}}));
  // A zero-area face (3, 0, 4) whose shared corner 0 lies strictly inside it.
  mesh.V.conservativeResize(5, 3);
  mesh.V.row(3) << -1, -1, 1;
  mesh.V.row(4) << 1, 1, -1;
  mesh.F << 0, 1, 2, 3, 0, 4;  // crosses the plane of face 0 at vertex 0 only
  EXPECT_TRUE(find_self_intersections(mesh).pairs.empty());
  mesh.V.row(3) << -1, -1, 0;
  mesh.V.row(4) << 1, 1, 0;
  mesh.F << 0, 1, 2, 3, 0, 4;  // runs along the diagonal of face 0
  EXPECT_EQ(find_self_intersections(mesh).pairs, (Pairs{{0, 1}}));
  mesh.V.row(4) << 0, 0, 0;  // corner 4 coincides with corner 0: a segment from 0 outward
  EXPECT_TRUE(find_self_intersections(mesh).pairs.empty());
  mesh.V.row(3) << 1, 1, 0;
  EXPECT_EQ(find_self_intersections(mesh).pairs, (Pairs{{0, 1}}));
}

TEST(SelfIntersections, BadInputThrows) {
  Mesh mesh;
  mesh.V.resize(3, 3);
  mesh.V << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  mesh.F.resize(2, 3);
  mesh.F << 0, 1, 2, 0, 1, 3;
  try {
    find_self_intersections(mesh);
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.location(), "face 1");
  }
  mesh.F << 0, 1, 2, 0, 2, 1;
  mesh.V(2, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(find_self_intersections(mesh), InputError);
  EXPECT_TRUE(find_self_intersections(Mesh{}).pairs.empty());
}

}  // namespace
}  // namespace reconfig::geometry
