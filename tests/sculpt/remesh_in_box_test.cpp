#include "reconfig/sculpt/remesh_in_box.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "reconfig/geometry/mass_properties.h"
#include "reconfig/geometry/mesh_check.h"
#include "reconfig/geometry/primitives.h"
#include "reconfig/geometry/self_intersections.h"
#include "reconfig/sculpt/sculpt_stroke.h"
#include "reconfig/sculpt/vertex_normals.h"

namespace reconfig::sculpt {
namespace {

using Triangle = std::array<double, 9>;

/// The triangles with no corner in `box`, by their coordinates (indices change).
/// Remeshing keeps them all (and may add new ones outside, halves of split triangles).
std::set<Triangle> faces_outside(const geometry::Mesh& mesh, const Eigen::AlignedBox3d& box) {
  std::set<Triangle> faces;
  for (int f = 0; f < mesh.face_count(); ++f) {
    Triangle t;
    bool outside = true;
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d p = mesh.V.row(mesh.F(f, i));
      outside = outside && !box.contains(p);
      for (int k = 0; k < 3; ++k) t[3 * i + k] = p[k];
    }
    if (outside) faces.insert(t);
  }
  return faces;
}

double longest_edge_touching(const geometry::Mesh& mesh, const Eigen::AlignedBox3d& box) {
  double longest = 0;
  for (int f = 0; f < mesh.face_count(); ++f)
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d a = mesh.V.row(mesh.F(f, i)), b = mesh.V.row(mesh.F(f, (i + 1) % 3));
      if (box.contains(a) || box.contains(b)) longest = std::max(longest, (a - b).norm());
    }
  return longest;
}

void expect_valid_solid(const geometry::Mesh& mesh) {
  const geometry::MeshReport report = geometry::check_mesh(mesh);
  EXPECT_TRUE(report.is_closed());
  EXPECT_TRUE(report.is_manifold());
  EXPECT_TRUE(report.is_oriented());
  EXPECT_TRUE(geometry::find_self_intersections(mesh, 1).pairs.empty());
}

TEST(RemeshInBox, SplitsLongEdgesInTheBoxOnlyAndStaysAClosedManifold) {
  geometry::Mesh mesh = geometry::make_sphere(1.0, 2);
  Eigen::MatrixX3d N = vertex_normals(mesh);
  const Eigen::AlignedBox3d box(Eigen::Vector3d(0.2, -2, -2), Eigen::Vector3d(2, 2, 2));
  const std::set<Triangle> outside = faces_outside(mesh, box);
  const double before = longest_edge_touching(mesh, box);
  const RemeshResult result = remesh_in_box(box, {before / 3, 0}, mesh, N);
  EXPECT_GT(result.splits, 100);
  EXPECT_EQ(result.collapses, 0);
  EXPECT_LE(longest_edge_touching(mesh, box), before / 3);
  const std::set<Triangle> after = faces_outside(mesh, box);
  EXPECT_TRUE(std::includes(after.begin(), after.end(), outside.begin(), outside.end()));
  EXPECT_EQ(N.rows(), mesh.V.rows());
  expect_valid_solid(mesh);
}

TEST(RemeshInBox, CollapsesShortEdgesKeepingAClosedManifold) {
  geometry::Mesh mesh = geometry::make_sphere(1.0, 4);
  Eigen::MatrixX3d N = vertex_normals(mesh);
  const Eigen::AlignedBox3d box(Eigen::Vector3d(-2, -2, 0.3), Eigen::Vector3d(2, 2, 2));
  const std::set<Triangle> outside = faces_outside(mesh, box);
  const int vertices = mesh.vertex_count();
  const double volume = geometry::mass_properties(mesh).volume;
  const RemeshResult result = remesh_in_box(box, {0.5, 0.12}, mesh, N);
  EXPECT_GT(result.collapses, 100);
  EXPECT_EQ(mesh.vertex_count(), vertices - result.collapses);
  EXPECT_EQ(faces_outside(mesh, box), outside);
  EXPECT_NEAR(geometry::mass_properties(mesh).volume, volume, 0.05 * volume);
  expect_valid_solid(mesh);
}

TEST(RemeshInBox, ALongPullKeepsItsResolutionAndStaysFreeOfSelfIntersections) {
  // A sphere tool dragged out of the surface by 10× its radius: without remeshing the few
  // vertices it holds stretch the triangles behind it into long slivers.
  geometry::Mesh mesh = geometry::make_sphere(1.0, 3);
  Eigen::MatrixX3d N = vertex_normals(mesh);
  const MovingTool pull{Tool::sphere(0.15, {1, 0, 0}, 0.2), ToolMotion::translation({1.5, 0.3, 0})};
  StrokeOptions options;
  options.remesh = {0.12, 0.03};
  geometry::Mesh plain = mesh;
  Eigen::MatrixX3d plain_normals = N;
  StrokeOptions no_remeshing;
  no_remeshing.check_self_intersections = false;
  ASSERT_TRUE(sculpt_mesh({pull}, no_remeshing, plain, plain_normals).applied);
  const Eigen::AlignedBox3d tip(Eigen::Vector3d(1.3, -1, -1), Eigen::Vector3d(3, 1, 1));
  ASSERT_GT(longest_edge_touching(plain, tip), 0.4);  // the slivers
  const StrokeResult result = sculpt_mesh({pull}, options, mesh, N);
  ASSERT_TRUE(result.applied) << result.refusal;
  EXPECT_GT(result.splits, 100);
  EXPECT_GT(result.min_jacobian_determinant, 0);
  EXPECT_LE(longest_edge_touching(mesh, tip), 0.13);
  EXPECT_NEAR(mesh.V.col(0).maxCoeff(), 2.5, 0.05);  // the vertex it held went along
  expect_valid_solid(mesh);
}

}  // namespace
}  // namespace reconfig::sculpt
