#include "reconfig/geometry/mesh_check.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>

#include "reconfig/geometry/load_mesh.h"
#include "reconfig/geometry/primitives.h"
#include "support/test_data.h"

namespace reconfig::geometry {
namespace {

Mesh two_meshes(const Mesh& a, const Mesh& b) {
  Mesh out;
  out.V.resize(a.vertex_count() + b.vertex_count(), 3);
  out.V << a.V, b.V;
  out.F.resize(a.face_count() + b.face_count(), 3);
  out.F << a.F, b.F.array() + a.vertex_count();
  return out;
}

Mesh translated(Mesh mesh, const Eigen::Vector3d& t) {
  mesh.V.rowwise() += t.transpose();
  return mesh;
}

MeshCheckOptions fast() {
  MeshCheckOptions options;
  options.check_self_intersections = false;
  return options;
}

TEST(CheckMesh, BoxIsAValidSolid) {
  const MeshReport report = check_mesh(make_box({1, 2, 3}));
  EXPECT_TRUE(report.is_valid_solid()) << report.summary();
  EXPECT_EQ(report.summary(), "closed, manifold, 12 triangles");
  EXPECT_EQ(report.vertex_count, 8);
  EXPECT_EQ(report.face_count, 12);
  EXPECT_DOUBLE_EQ(report.signed_volume, 6);
}

TEST(CheckMesh, MissingFaceLeavesThreeBoundaryEdges) {
  Mesh box = make_box({1, 1, 1});
  const Eigen::Vector3i removed = box.F.row(11);
  box.F.conservativeResize(11, 3);
  const MeshReport report = check_mesh(box, fast());
  EXPECT_FALSE(report.is_closed());
  EXPECT_FALSE(report.is_valid_solid());
  EXPECT_EQ(report.boundary_edges.count, 3);
  std::set<MeshEdge> expected;
  for (int k = 0; k < 3; ++k) expected.insert({std::min(removed[k], removed[(k + 1) % 3]), std::max(removed[k], removed[(k + 1) % 3])});
  EXPECT_EQ(std::set<MeshEdge>(report.boundary_edges.examples.begin(), report.boundary_edges.examples.end()), expected);
  EXPECT_TRUE(report.is_manifold());
  EXPECT_TRUE(report.is_oriented());
  EXPECT_EQ(report.summary().rfind("open: 3 boundary edges (e.g. ", 0), 0u) << report.summary();
}

TEST(CheckMesh, FlippedFaceGivesThreeInconsistentEdges) {
  Mesh box = make_box({1, 1, 1});
  std::swap(box.F(4, 1), box.F(4, 2));
  const MeshReport report = check_mesh(box, fast());
  EXPECT_TRUE(report.is_closed());
  EXPECT_TRUE(report.is_manifold());
  EXPECT_FALSE(report.is_oriented());
  EXPECT_EQ(report.inconsistent_edges.count, 3);
  EXPECT_FALSE(report.is_valid_solid());
}

TEST(CheckMesh, InsideOutBoxIsOrientedButNotOutward) {
  Mesh box = make_box({1, 1, 1});
  box.F.col(1).swap(box.F.col(2));
  const MeshReport report = check_mesh(box, fast());
  EXPECT_TRUE(report.is_oriented());
  EXPECT_FALSE(report.is_outward());
  EXPECT_DOUBLE_EQ(report.signed_volume, -1);
  EXPECT_FALSE(report.is_valid_solid());
  EXPECT_NE(report.summary().find("inside out"), std::string::npos) << report.summary();
}

TEST(CheckMesh, DuplicatedFaceMakesNonManifoldEdges) {
  Mesh box = make_box({1, 1, 1});
  box.F.conservativeResize(13, 3);
  box.F.row(12) = box.F.row(3);
  const MeshReport report = check_mesh(box, fast());
  EXPECT_EQ(report.non_manifold_edges.count, 3);
  EXPECT_FALSE(report.non_manifold_vertices.any());  // vertices of non-manifold edges are not counted twice
  EXPECT_FALSE(report.is_manifold());
}

TEST(CheckMesh, BoxesTouchingAtACornerPinchOneVertex) {
  Mesh a = make_box({1, 1, 1});
  Mesh b = translated(make_box({1, 1, 1}), {1, 1, 1});
  Mesh both = two_meshes(a, b);
  // Weld b's low corner (vertex 0 of b) onto a's high corner (vertex 7).
  for (int f = 0; f < both.face_count(); ++f)
    for (int k = 0; k < 3; ++k)
      if (both.F(f, k) == 8) both.F(f, k) = 7;
  const MeshReport report = check_mesh(both, fast());
  EXPECT_TRUE(report.is_closed());
  EXPECT_FALSE(report.non_manifold_edges.any());
  EXPECT_EQ(report.non_manifold_vertices.count, 1);
  EXPECT_EQ(report.non_manifold_vertices.examples, std::vector<int>{7});
  EXPECT_EQ(report.unreferenced_vertices.examples, std::vector<int>{8});
  EXPECT_EQ(report.component_count, 1);
  EXPECT_FALSE(report.is_valid_solid());
}

TEST(CheckMesh, DegenerateTriangles) {
  Mesh box = make_box({1, 1, 1});
  box.V.conservativeResize(9, 3);
  box.V.row(8) << 0, 0, 0;  // the center, on the diagonal from corner 0 to corner 7
  box.F.conservativeResize(15, 3);
  box.F.row(12) << 0, 0, 1;  // repeated index
  box.F.row(13) << 0, 7, 0;  // repeated index
  box.F.row(14) << 0, 8, 7;  // three collinear corners
  const MeshReport report = check_mesh(box, fast());
  EXPECT_EQ(report.degenerate_faces.count, 3);
  EXPECT_EQ(report.degenerate_faces.examples, (std::vector<int>{12, 13, 14}));

  // Nearly collinear, off by one ulp: exact arithmetic says it is a (thin) triangle.
  Mesh sliver;
  sliver.V.resize(3, 3);
  sliver.V << 0, 0, 0, 1, 1, 1, 0.5, 0.5, std::nextafter(0.5, 1.0);
  sliver.F.resize(1, 3);
  sliver.F << 0, 1, 2;
  EXPECT_EQ(check_mesh(sliver, fast()).degenerate_faces.count, 0);
  sliver.V(2, 2) = 0.5;
  EXPECT_EQ(check_mesh(sliver, fast()).degenerate_faces.count, 1);
}

TEST(CheckMesh, BadIndicesAndNonFiniteCoordinatesAreReportedNotFatal) {
  Mesh box = make_box({1, 1, 1});
  box.F(2, 0) = 8;
  box.F(5, 2) = -1;
  box.F(7, 1) = std::numeric_limits<int>::max();
  box.V(3, 1) = std::numeric_limits<double>::quiet_NaN();
  box.V(6, 0) = -std::numeric_limits<double>::infinity();
  const MeshReport report = check_mesh(box);
  EXPECT_EQ(report.out_of_range_faces.examples, (std::vector<int>{2, 5, 7}));
  EXPECT_EQ(report.non_finite_vertices.examples, (std::vector<int>{3, 6}));
  EXPECT_FALSE(report.is_closed());
  EXPECT_FALSE(report.is_valid_solid());
  EXPECT_FALSE(report.self_intersections_checked);
  EXPECT_NE(report.summary().find("3 faces with out-of-range indices (e.g. 2, 5, 7)"), std::string::npos)
      << report.summary();
}

TEST(CheckMesh, EmptyMeshIsNotASolid) {
  const MeshReport report = check_mesh(Mesh{});
  EXPECT_FALSE(report.is_closed());
  EXPECT_FALSE(report.is_valid_solid());
  EXPECT_EQ(report.component_count, 0);
  EXPECT_EQ(report.summary().rfind("no triangles", 0), 0u) << report.summary();
}

TEST(CheckMesh, CountsComponents) {
  const Mesh three =
      two_meshes(two_meshes(make_box({1, 1, 1}), translated(make_sphere(0.5, 1), {3, 0, 0})),
                 translated(make_cylinder(0.5, 1, 8), {6, 0, 0}));
  const MeshReport report = check_mesh(three);
  EXPECT_EQ(report.component_count, 3);
  EXPECT_TRUE(report.is_valid_solid()) << report.summary();
  EXPECT_NE(report.summary().find("3 components"), std::string::npos);
}

TEST(CheckMesh, ExamplesAreCappedButCountsAreNot) {
  Mesh sphere = make_sphere(1, 2);
  sphere.F.conservativeResize(sphere.face_count() / 2, 3);  // keep half: a long boundary
  MeshCheckOptions options = fast();
  options.max_examples = 2;
  const MeshReport report = check_mesh(sphere, options);
  EXPECT_GT(report.boundary_edges.count, 2);
  EXPECT_EQ(report.boundary_edges.examples.size(), 2u);
}

// --- Self-intersections (found by find_self_intersections) ----------------------------------

TEST(CheckMesh, InterpenetratingBoxesSelfIntersect) {
  const Mesh a = make_box({1, 1, 1});
  const Mesh both = two_meshes(a, translated(a, {0.5, 0.25, 0.125}));
  const MeshReport report = check_mesh(both);
  ASSERT_TRUE(report.self_intersections_checked);
  EXPECT_TRUE(report.is_closed());
  EXPECT_TRUE(report.is_manifold());
  EXPECT_TRUE(report.is_oriented());
  EXPECT_TRUE(report.self_intersections.any());
  EXPECT_FALSE(report.self_intersections_truncated);
  EXPECT_FALSE(report.is_valid_solid());
  for (const FacePair& pair : report.self_intersections.examples) {
    EXPECT_LT(pair[0], pair[1]);
    EXPECT_LT(pair[0], 12);  // one face of each box
    EXPECT_GE(pair[1], 12);
  }
  EXPECT_NE(report.summary().find("self-intersecting triangle pairs (e.g. "), std::string::npos) << report.summary();

  // Apart, they are a valid two-component solid.
  EXPECT_TRUE(check_mesh(two_meshes(a, translated(a, {1.5, 0, 0}))).is_valid_solid());

  // A cap of 0 pairs only tells whether there is any.
  MeshCheckOptions first_only;
  first_only.max_self_intersection_pairs = 0;
  const MeshReport any = check_mesh(both, first_only);
  EXPECT_EQ(any.self_intersections.count, 1);
  EXPECT_TRUE(any.self_intersections_truncated);
  EXPECT_NE(any.summary().find("at least 1 self-intersecting triangle pair;"), std::string::npos) << any.summary();

  // Faces left out for bad indices do not shift the reported face numbers.
  Mesh with_bad_face = both;
  with_bad_face.F.conservativeResize(both.face_count() + 1, 3);
  with_bad_face.F.bottomRows(both.face_count()) = both.F;
  with_bad_face.F.row(0) << 0, 1, 99;
  const MeshReport shifted = check_mesh(with_bad_face);
  ASSERT_EQ(shifted.self_intersections.count, report.self_intersections.count);
  for (std::size_t i = 0; i < report.self_intersections.examples.size(); ++i)
    EXPECT_EQ(shifted.self_intersections.examples[i],
              (FacePair{report.self_intersections.examples[i][0] + 1, report.self_intersections.examples[i][1] + 1}));
}

TEST(CheckMesh, CancelledSelfIntersectionSearchIsReportedAsNotChecked) {
  const Mesh a = make_sphere(1, 3);
  MeshCheckOptions options;
  options.progress = [](double) { return false; };
  const MeshReport report = check_mesh(two_meshes(a, translated(a, {0.5, 0, 0})), options);
  EXPECT_FALSE(report.self_intersections_checked);
  EXPECT_FALSE(report.self_intersections.any());
  EXPECT_NE(report.summary().find("self-intersections not checked"), std::string::npos);
}

// --- Oracle: the edge and vertex classification against a brute-force map-based count. -------

struct BruteForce {
  int boundary = 0, non_manifold = 0, inconsistent = 0, unreferenced = 0, components = 0;
};

BruteForce brute_force(const Mesh& mesh) {
  BruteForce out;
  std::map<std::pair<int, int>, std::vector<bool>> uses;  // undirected edge → directions (low→high?)
  std::set<int> used;
  for (int f = 0; f < mesh.face_count(); ++f) {
    const int a = mesh.F(f, 0), b = mesh.F(f, 1), c = mesh.F(f, 2);
    if (a == b || b == c || a == c) {
      used.insert({a, b, c});
      continue;
    }
    used.insert({a, b, c});
    for (auto [x, y] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}})
      uses[{std::min(x, y), std::max(x, y)}].push_back(x < y);
  }
  for (const auto& [edge, directions] : uses) {
    if (directions.size() == 1) ++out.boundary;
    if (directions.size() > 2) ++out.non_manifold;
    if (directions.size() == 2 && directions[0] == directions[1]) ++out.inconsistent;
  }
  out.unreferenced = mesh.vertex_count() - static_cast<int>(used.size());
  // Components: flood fill over the vertex adjacency.
  std::map<int, std::set<int>> neighbours;
  for (int f = 0; f < mesh.face_count(); ++f)
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j) neighbours[mesh.F(f, k)].insert(mesh.F(f, j));
  std::set<int> seen;
  for (int v : used) {
    if (seen.count(v)) continue;
    ++out.components;
    std::vector<int> stack{v};
    seen.insert(v);
    while (!stack.empty()) {
      const int x = stack.back();
      stack.pop_back();
      for (int y : neighbours[x])
        if (seen.insert(y).second) stack.push_back(y);
    }
  }
  return out;
}

TEST(CheckMesh, MatchesBruteForceOnRandomlyDamagedMeshes) {
  std::mt19937 rng(2024);
  const Mesh base = two_meshes(make_sphere(1, 1), translated(make_cylinder(1, 1, 6), {5, 0, 0}));
  for (int trial = 0; trial < 300; ++trial) {
    Mesh mesh = base;
    std::uniform_int_distribution<int> face(0, mesh.face_count() - 1), vertex(0, mesh.vertex_count() - 1);
    const int edits = trial % 8;
    for (int e = 0; e < edits; ++e) {
      const int f = face(rng);
      switch (rng() % 5) {
        case 0: std::swap(mesh.F(f, 0), mesh.F(f, 1)); break;       // flip
        case 1: mesh.F(f, static_cast<int>(rng() % 3)) = vertex(rng); break;  // rewire a corner
        case 2: mesh.F.row(f) = mesh.F.row(face(rng)); break;       // duplicate another face
        case 3:                                                     // delete (swap with the last)
          mesh.F.row(f) = mesh.F.row(mesh.face_count() - 1);
          mesh.F.conservativeResize(mesh.face_count() - 1, 3);
          face = std::uniform_int_distribution<int>(0, mesh.face_count() - 1);
          break;
        default: mesh.F(f, 2) = mesh.F(f, 0); break;  // collapse
      }
    }
    const MeshReport report = check_mesh(mesh, fast());
    const BruteForce expected = brute_force(mesh);
    SCOPED_TRACE(trial);
    EXPECT_EQ(report.boundary_edges.count, expected.boundary);
    EXPECT_EQ(report.non_manifold_edges.count, expected.non_manifold);
    EXPECT_EQ(report.inconsistent_edges.count, expected.inconsistent);
    EXPECT_EQ(report.unreferenced_vertices.count, expected.unreferenced);
    EXPECT_EQ(report.component_count, expected.components);
    if (edits == 0) {
      EXPECT_TRUE(report.is_valid_solid());
    }
  }
}

TEST(CheckMesh, NeverCrashesOnRandomGarbage) {
  std::mt19937 rng(99);
  for (int trial = 0; trial < 300; ++trial) {
    Mesh mesh;
    const int n = static_cast<int>(rng() % 12), m = static_cast<int>(rng() % 20);
    mesh.V = Eigen::MatrixX3d::Random(n, 3);
    if (n > 0 && rng() % 4 == 0) mesh.V(static_cast<int>(rng() % n), 1) = std::numeric_limits<double>::quiet_NaN();
    mesh.F.resize(m, 3);
    for (int f = 0; f < m; ++f)
      for (int k = 0; k < 3; ++k) mesh.F(f, k) = static_cast<int>(rng() % 16) - 2;
    const MeshReport report = check_mesh(mesh);
    EXPECT_FALSE(report.summary().empty());
  }
}

// --- Real meshes ----------------------------------------------------------------------------

TEST(CheckMesh, ClosedCgalMeshesAreValidSolids) {
  for (const char* name : {"cube.off", "elephant.off", "fandisk.off", "knot1.off", "bunny00.off"}) {
    SCOPED_TRACE(name);
    const MeshReport report = check_mesh(load_mesh(reconfig::testing::cgal_mesh(name)));
    EXPECT_TRUE(report.is_valid_solid()) << report.summary();
    EXPECT_TRUE(report.self_intersections_checked);
    EXPECT_EQ(report.component_count, 1);
  }
}

TEST(CheckMesh, BrokenCgalMeshesReportWhatIsWrong) {
  auto check = [](const char* name) { return check_mesh(load_mesh(reconfig::testing::cgal_mesh(name))); };
  const MeshReport shuffled = check("cube-shuffled.off");  // faces flipped at random
  EXPECT_TRUE(shuffled.is_closed());
  EXPECT_FALSE(shuffled.is_oriented());
  const MeshReport inverted = check("tetrahedron.off");  // consistently inward
  EXPECT_TRUE(inverted.is_oriented());
  EXPECT_FALSE(inverted.is_outward());
  EXPECT_EQ(inverted.summary(), "inside out (negative volume); 4 triangles");
  const MeshReport pierced = check("tetra_intersected_by_triangle.off");
  EXPECT_EQ(pierced.self_intersections.count, 1);
  EXPECT_EQ(pierced.boundary_edges.count, 3);  // the loose triangle
  const MeshReport sliding = check("degtri_sliding.off");
  EXPECT_TRUE(sliding.degenerate_faces.any());
}

TEST(CheckMesh, OpenCgalMeshesReportTheirHoles) {
  for (const char* name : {"elephant-with-holes.off", "cube-ouvert.off"}) {
    SCOPED_TRACE(name);
    const MeshReport report = check_mesh(load_mesh(reconfig::testing::cgal_mesh(name)), fast());
    EXPECT_FALSE(report.is_closed());
    EXPECT_GT(report.boundary_edges.count, 0);
    EXPECT_FALSE(report.is_valid_solid());
    EXPECT_EQ(report.summary().rfind("open: ", 0), 0u) << report.summary();
  }
}

}  // namespace
}  // namespace reconfig::geometry
