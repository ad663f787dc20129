#include "baked_tool_cache.h"

#include <gtest/gtest.h>

#include "reconfig/geometry/primitives.h"

namespace reconfig::studio {
namespace {

Eigen::Isometry3d shifted(double x) { return Eigen::Isometry3d(Eigen::Translation3d(x, 0, 0)); }

TEST(BakedToolCache, BakesOnceWhileNothingChanges) {
  BakedToolCache cache;
  const geometry::Mesh box = geometry::make_box(Eigen::Vector3d(1, 2, 3));
  const BakedToolCache::Baked* first = cache.bake(box, shifted(0.5), 0.01);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(cache.bake(box, shifted(0.5), 0.01), first);
  EXPECT_EQ(cache.bakes(), 1);
  // The baked tool is the part where it is: its distance is the box's, moved (exact within
  // the coating, and inside).
  EXPECT_NEAR(first->center.x(), 0.5, 1e-12);
  EXPECT_NEAR(first->tool.distance(Eigen::Vector3d(1.005, 0, 0)), 0.005, 1e-12);
  EXPECT_NEAR(first->tool.distance(Eigen::Vector3d(0.995, 0, 0)), -0.005, 1e-12);
}

TEST(BakedToolCache, RebakesWhenTheMeshThePlacementOrTheCoatingChanges) {
  BakedToolCache cache;
  geometry::Mesh box = geometry::make_box(Eigen::Vector3d(1, 1, 1));
  ASSERT_NE(cache.bake(box, shifted(0), 0.01), nullptr);
  ASSERT_NE(cache.bake(box, shifted(1e-12), 0.01), nullptr);  // moved, however little
  EXPECT_EQ(cache.bakes(), 2);
  ASSERT_NE(cache.bake(box, shifted(1e-12), 0.02), nullptr);
  EXPECT_EQ(cache.bakes(), 3);
  box.V(0, 0) += 1e-9;  // the part was edited
  const BakedToolCache::Baked* edited = cache.bake(box, shifted(1e-12), 0.02);
  ASSERT_NE(edited, nullptr);
  EXPECT_EQ(cache.bakes(), 4);
  EXPECT_EQ(edited->mesh.V(0, 0), box.V(0, 0) + 1e-12);
}

TEST(BakedToolCache, AMeshThatLostItsLastFacesIsNotTheOneBakedBefore) {
  BakedToolCache cache;
  const geometry::Mesh box = geometry::make_box(Eigen::Vector3d(1, 1, 1));
  ASSERT_NE(cache.bake(box, shifted(0), 0.01), nullptr);
  geometry::Mesh fewer = box;  // the same faces but the last: what a remeshing undo can leave
  fewer.F.conservativeResize(box.F.rows() - 1, 3);
  EXPECT_EQ(cache.bake(fewer, shifted(0), 0.01), nullptr);  // open: refused, not the closed box
  EXPECT_EQ(cache.bakes(), 2);
  geometry::Mesh more_vertices = box;  // an unused vertex added: a different mesh
  more_vertices.V.conservativeResize(box.V.rows() + 1, 3);
  more_vertices.V.row(box.V.rows()) = Eigen::RowVector3d(5, 5, 5);
  cache.bake(more_vertices, shifted(0), 0.01);
  EXPECT_EQ(cache.bakes(), 3);
}

TEST(BakedToolCache, AnOpenMeshIsNoToolAndStaysRefused) {
  BakedToolCache cache;
  geometry::Mesh open = geometry::make_box(Eigen::Vector3d(1, 1, 1));
  open.F.conservativeResize(open.F.rows() - 1, 3);  // a face missing
  EXPECT_EQ(cache.bake(open, shifted(0), 0.01), nullptr);
  EXPECT_EQ(cache.bake(open, shifted(0), 0.01), nullptr);
  EXPECT_EQ(cache.bakes(), 1);
  EXPECT_NE(cache.bake(geometry::make_box(Eigen::Vector3d(1, 1, 1)), shifted(0), 0.01), nullptr);
}

}  // namespace
}  // namespace reconfig::studio
