#include "reconfig/geometry/triangle_bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

#include "exact_kernels_test_util.h"
#include "reconfig/geometry/closest_point_on_triangle.h"
#include "support/random_soup.h"

namespace reconfig::geometry {
namespace {

using Eigen::AlignedBox3d;
using Eigen::Vector3d;
using Pairs = std::vector<std::pair<int, int>>;

AlignedBox3d face_box(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, int f) {
  AlignedBox3d box;
  for (int c = 0; c < 3; ++c) box.extend(Vector3d(V.row(F(f, c)).transpose()));
  return box;
}

/// Closed boxes overlap, written out coordinate by coordinate (independent of Eigen's).
bool overlap(const AlignedBox3d& a, const AlignedBox3d& b) {
  for (int d = 0; d < 3; ++d)
    if (a.max()[d] < b.min()[d] || b.max()[d] < a.min()[d]) return false;
  return true;
}

/// A triangle soup: n triangles of size ~`size` around points of the unit cube; coordinates
/// snapped to a 1/64 grid so that touching boxes (equal coordinates) are common.
Mesh random_soup(std::mt19937& rng, int n, double size) {
  return testing::random_soup(rng, n, {.min_size = size, .max_size = size, .grid = 1.0 / 64});
}

Pairs brute_pairs(const Mesh& a, const Mesh& b) {
  Pairs pairs;
  for (int f = 0; f < a.face_count(); ++f)
    for (int g = 0; g < b.face_count(); ++g)
      if (overlap(face_box(a.V, a.F, f), face_box(b.V, b.F, g))) pairs.emplace_back(f, g);
  return pairs;
}

Pairs bvh_pairs(const TriangleBvh& a, const TriangleBvh& b) {
  Pairs pairs;
  a.for_each_overlapping_pair(b, [&](int f, int g) { pairs.emplace_back(f, g); });
  std::sort(pairs.begin(), pairs.end());
  EXPECT_TRUE(std::adjacent_find(pairs.begin(), pairs.end()) == pairs.end()) << "a pair visited twice";
  return pairs;
}

std::vector<int> box_query(const TriangleBvh& bvh, const AlignedBox3d& box) {
  std::vector<int> faces;
  bvh.for_each_overlapping(box, [&](int f) { faces.push_back(f); });
  std::sort(faces.begin(), faces.end());
  EXPECT_TRUE(std::adjacent_find(faces.begin(), faces.end()) == faces.end()) << "a face visited twice";
  return faces;
}

std::vector<int> brute_box_query(const Mesh& mesh, const AlignedBox3d& box) {
  std::vector<int> faces;
  for (int f = 0; f < mesh.face_count(); ++f)
    if (overlap(face_box(mesh.V, mesh.F, f), box)) faces.push_back(f);
  return faces;
}

TEST(TriangleBvh, BoxQueriesMatchBruteForceOnSoups) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int n : {1, 3, 5, 17, 300}) {
    const Mesh soup = random_soup(rng, n, 0.1);
    const TriangleBvh bvh(soup.V, soup.F);
    for (int q = 0; q < 50; ++q) {
      AlignedBox3d box(Vector3d(unit(rng), unit(rng), unit(rng)));
      box.extend(Vector3d(unit(rng), unit(rng), unit(rng)) * (q % 2 ? 1.0 : 0.3));
      if (q % 5 == 0) box = face_box(soup.V, soup.F, q % n);  // shares planes with face boxes
      if (q % 7 == 0) box = AlignedBox3d(Vector3d(soup.V.row(soup.F(0, 0)).transpose()));  // a point box
      ASSERT_EQ(box_query(bvh, box), brute_box_query(soup, box)) << "n " << n << " query " << q;
    }
    EXPECT_TRUE(box_query(bvh, AlignedBox3d()).empty());  // an empty box overlaps nothing
  }
}

TEST(TriangleBvh, PairQueriesMatchBruteForceOnSoups) {
  std::mt19937 rng(12);
  for (auto [n, m] : {std::pair{1, 1}, {4, 9}, {60, 200}, {400, 250}}) {
    const Mesh a = random_soup(rng, n, 0.15), b = random_soup(rng, m, 0.05);
    const TriangleBvh ta(a.V, a.F), tb(b.V, b.F);
    const Pairs expected = brute_pairs(a, b);
    EXPECT_EQ(bvh_pairs(ta, tb), expected) << n << " × " << m;
    Pairs swapped;
    for (auto [f, g] : bvh_pairs(tb, ta)) swapped.emplace_back(g, f);
    std::sort(swapped.begin(), swapped.end());
    EXPECT_EQ(swapped, expected);
    if (n == 400) {
      EXPECT_GT(expected.size(), 50u);  // the test is not vacuous
    }
  }
}

TEST(TriangleBvh, MovedPairQueriesFindEveryPairWhoseMovedBoxesOverlap) {
  std::mt19937 rng(13);
  std::normal_distribution<double> normal(0, 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::size_t found_total = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const Mesh a = random_soup(rng, 300, 0.15), b = random_soup(rng, 200, 0.15);
    Eigen::Isometry3d b_to_a = Eigen::Isometry3d::Identity();
    b_to_a.linear() = Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized().toRotationMatrix();
    b_to_a.translation() = 0.3 * (Vector3d(unit(rng), unit(rng), unit(rng)) - Vector3d::Constant(0.5));
    const Eigen::MatrixX3d moved = (b.V * b_to_a.linear().transpose()).rowwise() + b_to_a.translation().transpose();
    Pairs visited;
    TriangleBvh(a.V, a.F).for_each_overlapping_pair(TriangleBvh(b.V, b.F), b_to_a,
                                                    [&](int f, int g) { visited.emplace_back(f, g); });
    std::sort(visited.begin(), visited.end());
    EXPECT_TRUE(std::adjacent_find(visited.begin(), visited.end()) == visited.end()) << "a pair visited twice";
    // Every pair whose moved triangle boxes overlap is visited (the tree may visit more).
    const Pairs expected = brute_pairs(a, Mesh{moved, b.F});
    EXPECT_TRUE(std::includes(visited.begin(), visited.end(), expected.begin(), expected.end())) << trial;
    found_total += expected.size();
  }
  EXPECT_GT(found_total, 100u);  // the test is not vacuous
}

TEST(TriangleBvh, PlacedPairsCarryTheirCornersAndLeafPositions) {
  std::mt19937 rng(29);
  std::normal_distribution<double> normal(0, 1);
  std::size_t found_total = 0;
  for (int trial = 0; trial < 8; ++trial) {
    const Mesh a = random_soup(rng, 250, 0.15), b = random_soup(rng, 180, 0.15);
    Eigen::Isometry3d b_to_a = Eigen::Isometry3d::Identity();
    b_to_a.linear() = Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized().toRotationMatrix();
    b_to_a.translation() = 0.1 * Vector3d(normal(rng), normal(rng), normal(rng));
    const TriangleBvh ta(a.V, a.F), tb(b.V, b.F);
    Pairs plain, placed;
    ta.for_each_overlapping_pair(tb, b_to_a, [&](int f, int g) { plain.emplace_back(f, g); });
    ta.for_each_overlapping_pair(tb, b_to_a, [&](const TriangleBvh::PlacedPair& pair) {
      placed.emplace_back(pair.f, pair.g);
      EXPECT_EQ(ta.leaf_order()[pair.f_position], pair.f);
      EXPECT_EQ(tb.leaf_order()[pair.g_position], pair.g);
      for (int k = 0; k < 3; ++k) {
        // f's rest corners, and g's moved as `b_to_a * corner`: the same doubles.
        EXPECT_EQ(pair.f_corners[k], Vector3d(a.V.row(a.F(pair.f, k)).transpose()));
        EXPECT_EQ(pair.g_corners[k], b_to_a * Vector3d(b.V.row(b.F(pair.g, k)).transpose()));
      }
    });
    // The same pairs in the same order as the plain placed query.
    EXPECT_EQ(placed, plain) << trial;
    // The tree's leaf-ordered corners are f's corners in F's order.
    for (std::size_t k = 0; k < ta.leaf_order().size(); ++k)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(ta.leaf_corners()[k][c], Vector3d(a.V.row(a.F(ta.leaf_order()[k], c)).transpose()));
    found_total += placed.size();
  }
  EXPECT_GT(found_total, 100u);  // the test is not vacuous
}

TEST(TriangleBvh, PairsWithinADistanceIncludeEveryPairWhoseGrownBoxesOverlap) {
  std::mt19937 rng(17);
  std::normal_distribution<double> normal(0, 1);
  std::size_t found_total = 0, beyond_overlap = 0;
  for (int trial = 0; trial < 8; ++trial) {
    const Mesh a = random_soup(rng, 200, 0.1), b = random_soup(rng, 150, 0.1);
    Eigen::Isometry3d b_to_a = Eigen::Isometry3d::Identity();
    b_to_a.linear() = Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized().toRotationMatrix();
    const Eigen::MatrixX3d moved = (b.V * b_to_a.linear().transpose()).rowwise() + b_to_a.translation().transpose();
    const double distance = 0.05;
    Pairs visited;
    TriangleBvh(a.V, a.F).for_each_pair_within(TriangleBvh(b.V, b.F), b_to_a, distance,
                                               [&](int f, int g) { visited.emplace_back(f, g); });
    std::sort(visited.begin(), visited.end());
    EXPECT_TRUE(std::adjacent_find(visited.begin(), visited.end()) == visited.end()) << "a pair visited twice";
    // Brute force: the moved triangles' boxes, grown by the distance, overlap.
    Pairs expected;
    for (int f = 0; f < a.face_count(); ++f)
      for (int g = 0; g < b.face_count(); ++g) {
        AlignedBox3d fa, gb;
        for (int k = 0; k < 3; ++k) {
          fa.extend(Vector3d(a.V.row(a.F(f, k))));
          gb.extend(Vector3d(moved.row(b.F(g, k))));
        }
        gb.min().array() -= distance;
        gb.max().array() += distance;
        if (fa.intersects(gb)) expected.emplace_back(f, g);
      }
    EXPECT_TRUE(std::includes(visited.begin(), visited.end(), expected.begin(), expected.end())) << trial;
    found_total += expected.size();
    Pairs overlapping;
    TriangleBvh(a.V, a.F).for_each_overlapping_pair(TriangleBvh(b.V, b.F), b_to_a,
                                                    [&](int f, int g) { overlapping.emplace_back(f, g); });
    beyond_overlap += visited.size() - overlapping.size();
  }
  EXPECT_GT(found_total, 100u);   // the test is not vacuous
  EXPECT_GT(beyond_overlap, 0u);  // and the distance finds more than the boxes' overlaps
}

TEST(TriangleBvh, NearestMatchesBruteForce) {
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> unit(-0.5, 1.5);
  const Mesh soup = random_soup(rng, 300, 0.1);
  const TriangleBvh bvh(soup.V, soup.F);
  for (int q = 0; q < 200; ++q) {
    const Vector3d p(unit(rng), unit(rng), unit(rng));
    double best = std::numeric_limits<double>::infinity();
    for (int f = 0; f < soup.face_count(); ++f)
      best = std::min(best, (closest_point_on_triangle(p, soup.V.row(soup.F(f, 0)).transpose(),
                                                       soup.V.row(soup.F(f, 1)).transpose(),
                                                       soup.V.row(soup.F(f, 2)).transpose())
                                 .point -
                             p)
                                .squaredNorm());
    const TriangleBvh::Nearest nearest = bvh.nearest(p);
    ASSERT_GE(nearest.triangle, 0);
    EXPECT_DOUBLE_EQ(nearest.squared_distance, best);
    EXPECT_DOUBLE_EQ((nearest.point - p).squaredNorm(), nearest.squared_distance);
  }
  EXPECT_EQ(TriangleBvh(Eigen::MatrixX3d(0, 3), Eigen::MatrixX3i(0, 3)).nearest(Vector3d::Zero()).triangle, -1);
}

TEST(TriangleBvh, TouchingBoxesCount) {
  // Two triangles whose boxes share exactly the plane x = 1.
  Mesh a, b;
  a.V.resize(3, 3);
  a.V << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  a.F.resize(1, 3);
  a.F << 0, 1, 2;
  b.V = a.V;
  b.V.col(0).array() += 1.0;
  b.F = a.F;
  const TriangleBvh ta(a.V, a.F), tb(b.V, b.F);
  EXPECT_EQ(bvh_pairs(ta, tb), (Pairs{{0, 0}}));
  b.V.col(0).array() += 1e-15;
  const TriangleBvh tc(b.V, b.F);
  EXPECT_TRUE(bvh_pairs(ta, tc).empty());
}

TEST(TriangleBvh, BoundsAndBoxQueriesOnCgalMesh) {
  const Mesh mesh = testing::cgal_off("bunny00.off");
  ASSERT_GT(mesh.face_count(), 100);
  const TriangleBvh bvh(mesh.V, mesh.F);
  AlignedBox3d expected;
  for (int f = 0; f < mesh.face_count(); ++f) expected.extend(face_box(mesh.V, mesh.F, f));
  EXPECT_EQ(bvh.bounds().min(), expected.min());
  EXPECT_EQ(bvh.bounds().max(), expected.max());
  EXPECT_EQ(bvh.faces(), mesh.F);

  // Box queries around random vertices.
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> vertex(0, mesh.vertex_count() - 1);
  const double radius = 0.02 * expected.diagonal().norm();
  for (int q = 0; q < 30; ++q) {
    const Vector3d c = mesh.V.row(vertex(rng)).transpose();
    const AlignedBox3d box(c - Vector3d::Constant(radius), c + Vector3d::Constant(radius));
    ASSERT_EQ(box_query(bvh, box), brute_box_query(mesh, box));
  }
}

TEST(TriangleBvh, SelfPairsOnCgalMesh) {
  // Self pairs: every ordered pair (f, g) with overlapping boxes, including (f, f).
  const Mesh mesh = testing::cgal_off("elephant.off");
  const TriangleBvh bvh(mesh.V, mesh.F);
  std::vector<AlignedBox3d> boxes;
  for (int f = 0; f < mesh.face_count(); ++f) boxes.push_back(face_box(mesh.V, mesh.F, f));
  const int limit = 2000;  // brute force for the first faces against all, to stay quick
  Pairs want, got;
  for (int f = 0; f < limit; ++f)
    for (int g = 0; g < mesh.face_count(); ++g)
      if (overlap(boxes[f], boxes[g])) want.emplace_back(f, g);
  for (auto [f, g] : bvh_pairs(bvh, bvh))
    if (f < limit) got.emplace_back(f, g);
  EXPECT_EQ(got, want);
  EXPECT_GT(want.size(), 10u * limit);  // adjacent faces' boxes overlap
}

TEST(TriangleBvh, EmptyMesh) {
  const TriangleBvh empty(Eigen::MatrixX3d(0, 3), Eigen::MatrixX3i(0, 3));
  EXPECT_TRUE(empty.bounds().isEmpty());
  EXPECT_TRUE(box_query(empty, AlignedBox3d(Vector3d(-1, -1, -1), Vector3d(1, 1, 1))).empty());
  std::mt19937 rng(1);
  const Mesh soup = random_soup(rng, 10, 0.1);
  const TriangleBvh full(soup.V, soup.F);
  EXPECT_TRUE(bvh_pairs(empty, full).empty());
  EXPECT_TRUE(bvh_pairs(full, empty).empty());
}

}  // namespace
}  // namespace reconfig::geometry
