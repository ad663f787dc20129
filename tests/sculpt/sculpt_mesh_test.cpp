#include "reconfig/sculpt/sculpt_mesh.h"

#include <gtest/gtest.h>

#include <random>

#include "reconfig/geometry/primitives.h"
#include "reconfig/sculpt/sculpt_stroke.h"
#include "reconfig/sculpt/vertex_normals.h"

namespace reconfig::sculpt {
namespace {

TEST(SculptMesh, ResizesAndAssignmentsKeepTheRowsAPlainMatrixKeeps) {
  // Random growth, shrinking and row writes against plain matrices resized each time (the
  // reference): the rows kept are the same, bit for bit, whatever the room kept.
  std::mt19937 random(23);
  geometry::Mesh start = geometry::make_sphere(1.0, 1);
  for (const bool normals : {true, false}) {
    Eigen::MatrixX3d N = normals ? vertex_normals(start) : Eigen::MatrixX3d(0, 3);
    SculptMesh mesh(start, N);
    Eigen::MatrixX3d V = start.V;
    Eigen::MatrixX3i F = start.F;
    for (int step = 0; step < 300; ++step) {
      const int vertices = static_cast<int>(random() % 400), faces = static_cast<int>(random() % 800);
      const int kept_vertices = std::min<int>(vertices, V.rows()), kept_faces = std::min<int>(faces, F.rows());
      mesh.resize(vertices, faces);
      V.conservativeResize(vertices, 3);
      F.conservativeResize(faces, 3);
      if (normals) N.conservativeResize(vertices, 3);
      for (int v = kept_vertices; v < vertices; ++v) {  // the new rows, written in both
        V.row(v) = Eigen::RowVector3d::Random();
        mesh.V().row(v) = V.row(v);
        if (normals) mesh.N().row(v) = N.row(v) = Eigen::RowVector3d::Random();
      }
      for (int f = kept_faces; f < faces; ++f) mesh.F().row(f) = F.row(f) = Eigen::RowVector3i::Random();
      if (step % 50 == 49) mesh.assign(V, F, N);
      ASSERT_EQ(mesh.vertex_count(), vertices);
      ASSERT_EQ(mesh.face_count(), faces);
      ASSERT_TRUE(mesh.V() == V) << step;
      ASSERT_TRUE(mesh.F() == F) << step;
      ASSERT_EQ(mesh.N().rows(), normals ? vertices : 0);
      if (normals) {
        ASSERT_TRUE(mesh.N() == N) << step;
      }
      ASSERT_TRUE(mesh.mesh().V == V && mesh.mesh().F == F);
    }
  }
}

TEST(SculptMesh, AdoptAndReleaseHandTheMatricesBackUnchanged) {
  geometry::Mesh mesh = geometry::make_sphere(1.0, 2);
  const geometry::Mesh before = mesh;
  Eigen::MatrixX3d N = vertex_normals(mesh);
  const Eigen::MatrixX3d normals_before = N;
  MeshIndex index(mesh);
  SculptMesh adopted = SculptMesh::adopt(std::move(mesh), std::move(N), std::move(index));
  EXPECT_EQ(adopted.vertex_count(), before.vertex_count());
  EXPECT_TRUE(adopted.has_normals());
  EXPECT_EQ(adopted.index().vertex_count(), before.vertex_count());
  adopted.release(mesh, N, index);
  EXPECT_TRUE(mesh.V == before.V && mesh.F == before.F && N == normals_before);
  EXPECT_EQ(index.face_count(), before.face_count());
  EXPECT_EQ(adopted.vertex_count(), 0);
}

TEST(SculptMesh, ADragGivesWhatStrokesOnAPlainMeshGiveBitForBit) {
  // The same drag (splits, collapses, a refused move) on a SculptMesh kept from stroke to stroke
  // and on a geometry::Mesh with its index: the same results, vertices, faces and normals.
  std::mt19937 random(41);
  std::uniform_real_distribution<double> unit(-1, 1);
  geometry::Mesh plain = geometry::make_sphere(1.0, 3);
  Eigen::MatrixX3d plain_N = vertex_normals(plain);
  MeshIndex plain_index(plain);
  SculptMesh sculpted(plain, plain_N);
  StrokeOptions options;
  options.remesh = {0.2, 0.09};
  Tool tool = Tool::sphere(0.25, {1, 0, 0}, 0.3);
  int splits = 0, collapses = 0, refused = 0;
  for (int move = 0; move < 12; ++move) {
    const Eigen::Vector3d d = 0.3 * Eigen::Vector3d(unit(random), unit(random), unit(random));
    StrokeOptions these = options;
    these.substeps = move % 5 == 4 ? 1 : 0;  // now and then too few sub-steps: may be refused
    const std::vector<MovingTool> stroke = {{tool, ToolMotion::translation(move % 5 == 4 ? 20 * d : d)}};
    const StrokeResult a = sculpt_mesh(stroke, these, plain, plain_N, plain_index);
    const StrokeResult b = sculpt_mesh(stroke, these, sculpted);
    ASSERT_EQ(a.applied, b.applied) << move;
    ASSERT_EQ(a.refusal, b.refusal);
    ASSERT_EQ(a.splits, b.splits);
    ASSERT_EQ(a.collapses, b.collapses);
    ASSERT_EQ(a.vertices_moved, b.vertices_moved);
    ASSERT_EQ(a.min_jacobian_determinant, b.min_jacobian_determinant);
    ASSERT_TRUE(sculpted.V() == plain.V) << move;
    ASSERT_TRUE(sculpted.F() == plain.F) << move;
    ASSERT_TRUE(sculpted.N() == plain_N) << move;
    ASSERT_EQ(sculpted.index().vertex_count(), plain.vertex_count());
    ASSERT_EQ(sculpted.index().face_count(), plain.face_count());
    for (int trial = 0; trial < 20; ++trial) {
      const Eigen::Vector3d c(unit(random), unit(random), unit(random));
      const Eigen::AlignedBox3d box(c - Eigen::Vector3d::Constant(0.4), c + Eigen::Vector3d::Constant(0.4));
      ASSERT_EQ(sculpted.index().vertices_in(box, sculpted.V()), plain_index.vertices_in(box, plain.V));
    }
    if (a.applied) tool = a.tools.front();
    splits += a.splits;
    collapses += a.collapses;
    refused += !a.applied;
  }
  EXPECT_GT(splits, 0);
  EXPECT_GT(collapses, 0);
  EXPECT_GT(refused, 0);
}

}  // namespace
}  // namespace reconfig::sculpt
