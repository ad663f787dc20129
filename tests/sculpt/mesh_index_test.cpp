#include "reconfig/sculpt/mesh_index.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "reconfig/geometry/primitives.h"
#include "reconfig/sculpt/sculpt_stroke.h"
#include "reconfig/sculpt/vertex_normals.h"

namespace reconfig::sculpt {
namespace {

/// The vertices in `box`, by a scan of every vertex (the reference).
std::vector<int> scan(const Eigen::AlignedBox3d& box, const Eigen::MatrixX3d& V) {
  std::vector<int> found;
  for (int v = 0; v < V.rows(); ++v)
    if (box.contains(V.row(v).transpose())) found.push_back(v);
  return found;
}

Eigen::AlignedBox3d random_box(std::mt19937& random, double extent) {
  std::uniform_real_distribution<double> unit(-1, 1), size(0, 1);
  const Eigen::Vector3d center = extent * Eigen::Vector3d(unit(random), unit(random), unit(random));
  const double half = extent * std::pow(size(random), 2);  // from tiny boxes to the whole mesh
  return {center - Eigen::Vector3d::Constant(half), center + Eigen::Vector3d::Constant(half)};
}

/// The faces of every vertex, by a scan of every face (the reference), as sets.
std::vector<std::set<int>> faces_by_scan(const geometry::Mesh& mesh) {
  std::vector<std::set<int>> faces(mesh.vertex_count());
  for (int f = 0; f < mesh.face_count(); ++f)
    for (int i = 0; i < 3; ++i) faces[mesh.F(f, i)].insert(f);
  return faces;
}

void expect_same_as_scans(const MeshIndex& index, const geometry::Mesh& mesh, std::mt19937& random, double extent) {
  ASSERT_EQ(index.vertex_count(), mesh.vertex_count());
  ASSERT_EQ(index.face_count(), mesh.face_count());
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::AlignedBox3d box = random_box(random, extent);
    ASSERT_EQ(index.vertices_in(box, mesh.V), scan(box, mesh.V)) << "trial " << trial;
  }
  const std::vector<std::set<int>> faces = faces_by_scan(mesh);
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    const std::set<int> indexed(index.faces_of(v).begin(), index.faces_of(v).end());
    ASSERT_EQ(indexed, faces[v]) << "vertex " << v;
    ASSERT_EQ(indexed.size(), index.faces_of(v).size()) << "vertex " << v;  // no face twice
  }
}

TEST(MeshIndex, FindsTheVerticesAScanFinds) {
  std::mt19937 random(7);
  geometry::Mesh mesh = geometry::make_sphere(1.0, 3);
  std::normal_distribution<double> noise(0, 0.02);
  for (int v = 0; v < mesh.vertex_count(); ++v) mesh.V.row(v) += Eigen::RowVector3d(noise(random), noise(random), noise(random));
  for (double cell : {0.0, 0.01, 0.3, 5.0}) expect_same_as_scans(MeshIndex(mesh, cell), mesh, random, 1.3);
  // Boxes on cell boundaries and on vertices exactly (closed boxes).
  const MeshIndex index(mesh, 0.25);
  for (int v = 0; v < mesh.vertex_count(); v += 17) {
    const Eigen::AlignedBox3d box(mesh.V.row(v).transpose(), mesh.V.row(v).transpose());
    EXPECT_EQ(index.vertices_in(box, mesh.V), scan(box, mesh.V));
  }
  const Eigen::AlignedBox3d on_cells(Eigen::Vector3d(-0.5, -0.25, 0), Eigen::Vector3d(0.5, 0.25, 0.75));
  EXPECT_EQ(index.vertices_in(on_cells, mesh.V), scan(on_cells, mesh.V));
}

TEST(MeshIndex, FindsWhatAScanFindsOnFlatAndStretchedMeshes) {
  // The grid spans the mesh's box: flat along an axis, stretched by one far vertex (most cells
  // empty, the grid coarsened to bound its size), or a single point.
  std::mt19937 random(19);
  geometry::Mesh flat = geometry::make_sphere(1.0, 3);
  flat.V.col(2).setZero();
  geometry::Mesh stretched = geometry::make_sphere(1.0, 3);
  stretched.V.row(0) << 400, -300, 250;
  geometry::Mesh point = geometry::make_sphere(1.0, 0);
  point.V.setConstant(0.5);
  for (const geometry::Mesh* mesh : {&flat, &stretched, &point})
    for (double cell : {0.0, 0.001, 0.2}) expect_same_as_scans(MeshIndex(*mesh, cell), *mesh, random, 1.5);
  const MeshIndex far(stretched, 0.05);
  const Eigen::AlignedBox3d around_far(Eigen::Vector3d(399, -301, 249), Eigen::Vector3d(401, -299, 251));
  EXPECT_EQ(far.vertices_in(around_far, stretched.V), std::vector<int>{0});
}

TEST(MeshIndex, FollowsMovedAndAddedVertices) {
  std::mt19937 random(11);
  geometry::Mesh mesh = geometry::make_sphere(1.0, 2);
  MeshIndex index(mesh, 0.2);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> pick(0, mesh.vertex_count() - 1);
  for (int move = 0; move < 500; ++move) {  // small moves, and far jumps (even out of the grid)
    const int v = pick(random);
    const Eigen::Vector3d from = mesh.V.row(v).transpose();
    const double reach = move % 10 == 0 ? 3.0 : 0.1;
    const Eigen::Vector3d to = from + reach * Eigen::Vector3d(unit(random), unit(random), unit(random));
    mesh.V.row(v) = to.transpose();
    index.move_vertex(v, from, to);
  }
  for (int added = 0; added < 50; ++added) {
    const Eigen::Vector3d p = 2.0 * Eigen::Vector3d(unit(random), unit(random), unit(random));
    mesh.V.conservativeResize(mesh.vertex_count() + 1, 3);
    mesh.V.bottomRows(1) = p.transpose();
    index.add_vertex(p);
  }
  for (int trial = 0; trial < 300; ++trial) {
    const Eigen::AlignedBox3d box = random_box(random, 3.0);
    ASSERT_EQ(index.vertices_in(box, mesh.V), scan(box, mesh.V)) << "trial " << trial;
  }
}

TEST(MeshIndex, StrokesKeepItUpToDate) {
  // A drag of strokes with remeshing (splits, then collapses), the index kept from stroke to
  // stroke: after each it is what indexing the mesh anew gives.
  std::mt19937 random(3);
  geometry::Mesh mesh = geometry::make_sphere(1.0, 3);
  Eigen::MatrixX3d N = vertex_normals(mesh);
  MeshIndex index(mesh);
  StrokeOptions options;
  options.remesh = {0.2, 0.09};
  options.check_self_intersections = false;
  Tool tool = Tool::sphere(0.25, {1, 0, 0}, 0.3);
  const Eigen::Vector3d moves[] = {{0.3, 0.1, 0}, {0.2, 0.2, 0.1}, {-0.4, -0.2, 0}, {-0.3, 0, -0.2}};
  int splits = 0, collapses = 0;
  for (const Eigen::Vector3d& d : moves) {
    const StrokeResult result = sculpt_mesh({{tool, ToolMotion::translation(d)}}, options, mesh, N, index);
    ASSERT_TRUE(result.applied) << result.refusal;
    splits += result.splits;
    collapses += result.collapses;
    tool = result.tools.front();
    expect_same_as_scans(index, mesh, random, 1.6);
  }
  EXPECT_GT(splits, 0);
  EXPECT_GT(collapses, 0);
}

}  // namespace
}  // namespace reconfig::sculpt
