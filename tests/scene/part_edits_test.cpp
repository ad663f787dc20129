#include "reconfig/scene/part_edits.h"

#include <gtest/gtest.h>

#include "reconfig/geometry/primitives.h"
#include "reconfig/scene/edits.h"
#include "edit_checks.h"
#include "support/random_scene.h"

namespace reconfig::scene {
namespace {

TEST(AddPart, AppendsAPrimitiveAndUndoRemovesIt) {
  Reconfigurable scene = testing::random_scene(1, {.parts = 3, .moving = 2});
  Reconfigurable edited = scene;
  History history;
  const DirtySet dirty = history.execute(edited, add_primitive_part("lid", BoxPrimitive{{0.2, 0.1, 0.05}}));
  EXPECT_TRUE(dirty.structure_changed);
  ASSERT_EQ(edited.parts.size(), 4u);
  EXPECT_EQ(edited.parts[3].name, "lid");
  EXPECT_EQ(edited.parts[3].mesh.F.rows(), 12);
  EXPECT_TRUE(edited.parts[3].center.isZero(1e-12));
  round_trip(scene, add_primitive_part("lid", CylinderPrimitive{0.1, 0.3}, Eigen::Vector3d(1, 0, 0)));
}

TEST(AddPart, FromAMeshHasItsCenterOfMassAsPivot) {
  Reconfigurable scene = testing::random_scene(2, {.parts = 2, .moving = 1});
  geometry::Mesh mesh = geometry::make_box({1, 1, 1});
  mesh.V.rowwise() += Eigen::RowVector3d(2, 0, 0);
  History history;
  history.execute(scene, add_part("shifted", mesh, MeshFile{"/tmp/shifted.obj"}));
  EXPECT_TRUE(scene.parts.back().center.isApprox(Eigen::Vector3d(2, 0, 0), 1e-12));
}

TEST(AddPart, RefusesBadInput) {
  Reconfigurable scene = testing::random_scene(3, {.parts = 2, .moving = 1});
  expect_refused(scene, add_primitive_part(scene.parts[0].name, SpherePrimitive{0.1}), "already a part named");
  expect_refused(scene, add_primitive_part("", SpherePrimitive{0.1}), "needs a name");
  expect_refused(scene, add_part("empty", geometry::Mesh{}, EditedMesh{}), "no triangles");
  expect_refused(scene, add_primitive_part("ball", SpherePrimitive{0.1}, Eigen::Vector3d(2, 0, 0)), "color");
  expect_refused(scene, add_primitive_part("flat", BoxPrimitive{{0.1, 0, 0.1}}), "sizes must be positive");
}

TEST(RenamePart, RenamesItsPosesAndTracksAndDirtiesNothing) {
  Reconfigurable scene = testing::random_scene(4, {.parts = 3, .moving = 2});
  const std::string old_name = scene.parts[0].name;
  ASSERT_TRUE(scene.transitions[0].tracks.count(old_name));
  Reconfigurable edited = scene;
  History history;
  EXPECT_TRUE(history.execute(edited, rename_part(old_name, "renamed")).empty());
  EXPECT_EQ(edited.parts[0].name, "renamed");
  EXPECT_TRUE(edited.transitions[0].tracks.count("renamed"));
  EXPECT_FALSE(edited.transitions[0].tracks.count(old_name));
  EXPECT_TRUE(edited.states[0].poses.count("renamed"));
  EXPECT_TRUE(round_trip(scene, rename_part(old_name, "renamed")).first.empty());
  expect_refused(scene, rename_part(old_name, scene.parts[1].name), "already a part named");
  expect_refused(scene, rename_part("nobody", "x"), "unknown part \"nobody\"");
}

TEST(RecolorPart, SetsTheColorAndDirtiesNothing) {
  Reconfigurable scene = testing::random_scene(5, {.parts = 2, .moving = 1});
  EXPECT_TRUE(round_trip(scene, recolor_part(scene.parts[1].name, Eigen::Vector3d(0.1, 0.2, 0.3))).first.empty());
  expect_refused(scene, recolor_part(scene.parts[1].name, Eigen::Vector3d(0.1, -0.2, 0.3)), "[0, 1]");
  expect_refused(scene, recolor_part("ghost", std::nullopt), "unknown part");
}

TEST(DuplicatePart, CopiesGeometryPosesAndTracks) {
  Reconfigurable scene = testing::random_scene(6, {.parts = 3, .moving = 2});
  const std::string name = scene.parts[0].name;
  Reconfigurable edited = scene;
  History history;
  EXPECT_TRUE(history.execute(edited, duplicate_part(name, "copy")).structure_changed);
  const int copy = edited.find_part("copy");
  ASSERT_EQ(copy, 3);
  EXPECT_EQ(edited.parts[copy].mesh.V, scene.parts[0].mesh.V);
  for (double t : {0.0, 0.37, 1.0}) {
    const motion::Pose a = edited.pose_at(0, 0, t), b = edited.pose_at(0, copy, t);
    EXPECT_EQ(a.translation, b.translation);
  }
  round_trip(scene, duplicate_part(name, "copy"));
  expect_refused(scene, duplicate_part(name, scene.parts[2].name), "already a part named");
  expect_refused(scene, duplicate_part("none", "copy"), "unknown part");
}

TEST(DeletePart, IsRefusedWhileATransitionMovesIt) {
  Reconfigurable scene = testing::random_scene(7, {.parts = 3, .moving = 2});
  const std::string moving = scene.parts[0].name;
  ASSERT_TRUE(scene.transitions[0].tracks.count(moving));
  expect_refused(scene, delete_part(moving), "moves in transition \"move\"");
  EXPECT_TRUE(round_trip(scene, delete_part(moving, true)).first.structure_changed);
  Reconfigurable edited = scene;
  History history;
  history.execute(edited, delete_part(moving, true));
  EXPECT_EQ(edited.find_part(moving), -1);
  EXPECT_FALSE(edited.transitions[0].tracks.count(moving));
  EXPECT_FALSE(edited.states[0].poses.count(moving));
  expect_refused(scene, delete_part("none"), "unknown part");
}

TEST(DeletePart, AStillPartGoesWithoutAsking) {
  Reconfigurable scene = testing::random_scene(8, {.parts = 3, .moving = 1});
  const std::string still = scene.parts[2].name;
  ASSERT_FALSE(scene.transitions[0].tracks.count(still));
  round_trip(scene, delete_part(still));
}

TEST(DeletePart, UndoPutsAMiddlePartBackInItsPlace) {
  Reconfigurable scene = testing::random_scene(9, {.parts = 4, .moving = 3});
  const Reconfigurable original = scene;
  History history;
  history.execute(scene, delete_part(scene.parts[1].name, true));
  history.execute(scene, add_primitive_part("new", SpherePrimitive{0.2}));
  history.undo(scene);
  history.undo(scene);
  EXPECT_TRUE(same_design(scene, original));
}

TEST(ReplacePartMesh, KeepsThePivotAndTakesTheNewSource) {
  Reconfigurable scene = testing::random_scene(10, {.parts = 2, .moving = 1});
  const Eigen::Vector3d pivot = scene.parts[0].center;
  geometry::Mesh mesh = geometry::make_box({0.3, 0.3, 0.3});
  mesh.V.rowwise() += Eigen::RowVector3d(0.5, 0, 0);
  Reconfigurable edited = scene;
  History history;
  const DirtySet dirty = history.execute(edited, replace_part_mesh(scene.parts[0].name, mesh, MeshFile{"/m/new.obj"}));
  EXPECT_EQ(dirty.geometry_changed, std::vector<int>{0});
  EXPECT_EQ(edited.parts[0].center, pivot);
  EXPECT_EQ(std::get<MeshFile>(edited.parts[0].source).path, "/m/new.obj");
  EXPECT_EQ(edited.states[1].pose_of(scene.parts[0].name).translation, scene.states[1].pose_of(scene.parts[0].name).translation);
  round_trip(scene, replace_part_mesh(scene.parts[0].name, mesh, MeshFile{"/m/new.obj"}));
  expect_refused(scene, replace_part_mesh(scene.parts[0].name, geometry::Mesh{}, EditedMesh{}), "no triangles");
}

}  // namespace
}  // namespace reconfig::scene
