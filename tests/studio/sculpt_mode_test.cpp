// The studio's sculpt mode driven through mouse events (headless): left-drags reshape the
// bench-table's armrests until `unfold` is collision-free, each stroke one undoable edit; a
// right-drag only places the tool; a refused move stops the stroke at its last good state; a
// drag on one of the tool's rings turns it and the part as the library's rotation stroke does,
// and the tool keeps its rotation from stroke to stroke.

#include <gtest/gtest.h>

#include <fmt/format.h>

#include "axis_angle.h"
#include "bench_table_unfold.h"
#include "reconfig/geometry/primitives.h"
#include "reconfig/geometry/self_intersections.h"
#include "reconfig/scene/edits.h"
#include "reconfig/sculpt/sculpt_stroke.h"
#include "script.h"

namespace reconfig::studio {
namespace {

using std::chrono::milliseconds;

class StudioSculptMode : public BenchTableUnfold {
 protected:
  /// The camera looks along −x (from the side), so drags along y and z stay in the view plane.
  void look_from_the_side() {
    studio().camera().yaw = 0;
    studio().camera().pitch = 0;
    frontend_->run_frame();
  }
  const geometry::Mesh& mesh_of(const char* name) { return scene().parts[part(name)].mesh; }
  /// A drag of the tool by `d` in the part's rest frame, as a script line (world offset).
  std::string drag_line(const Eigen::Vector3d& d, int steps = 8) {
    const Eigen::Vector3d world = studio().selected_pose()->rotation * d;
    return fmt::format("sculpt-drag {} {} {} steps {}\n", world.x(), world.y(), world.z(), steps);
  }
};

TEST_F(StudioSculptMode, LeftDragsReshapeTheArmrestsUntilUnfoldIsCollisionFree) {
  ASSERT_EQ(intervals_shown(), 2u);  // the backrest hits both armrests
  look_from_the_side();
  const geometry::Mesh right_before = mesh_of("armrest_right");
  for (const char* armrest : {"armrest_left", "armrest_right"}) {
    studio().select_part(part(armrest));
    run_script(*frontend_, "sculpt-mode on\nsculpt-tool box 0.2 0.2 0.2 0.08\n", "sculpt mode");
    studio().sculpt().settings().center = {0, -0.25, 0};  // beyond the armrest's back end
    const std::uint64_t version = studio().document()->version();
    run_script(*frontend_, drag_line({0, 0.14, 0}), "drag");
    EXPECT_GT(studio().document()->version(), version);
    EXPECT_FALSE(studio().sculpt().stroking());
    EXPECT_NE(studio().status().find("sculpted " + std::string(armrest)), std::string::npos) << studio().status();
    // The back end moved with the tool (to within a pixel: about 3 mm here).
    EXPECT_NEAR(mesh_of(armrest).V.col(1).minCoeff(), -0.19 + 0.14, 4e-3);
    EXPECT_TRUE(geometry::find_self_intersections(mesh_of(armrest), 1).pairs.empty());
  }
  run_script(*frontend_, "sculpt-mode off\n", "off");
  ASSERT_TRUE(frontend_->run_until_collisions_current(milliseconds(60000)));
  EXPECT_EQ(intervals_shown(), 0u);
  // The whole drag of the right armrest (eight moves) is one undoable edit.
  const geometry::Mesh left_sculpted = mesh_of("armrest_left");
  ASSERT_TRUE(studio().undo());
  EXPECT_EQ(mesh_of("armrest_right").V, right_before.V);
  EXPECT_EQ(mesh_of("armrest_right").F, right_before.F);
  EXPECT_EQ(mesh_of("armrest_left").V, left_sculpted.V);
  ASSERT_TRUE(frontend_->run_until_collisions_current(milliseconds(60000)));
  EXPECT_EQ(intervals_shown(), 1u);
}

TEST_F(StudioSculptMode, ARightDragPlacesTheToolOnTheSurfaceWithoutDeforming) {
  look_from_the_side();
  studio().select_part(part("armrest_left"));
  run_script(*frontend_, "sculpt-mode on\nsculpt-tool sphere 0.03 0 0 0.03\n", "sculpt mode");
  const geometry::Mesh before = mesh_of("armrest_left");
  const std::uint64_t version = studio().document()->version();
  // A point of the armrest's +x side (it faces the camera), in the world.
  const motion::Pose pose = *studio().selected_pose();
  const Eigen::Vector3d rest(0.025, 0.05, 0.01);
  const Eigen::Vector3d world = pose.apply(scene().parts[part("armrest_left")].center, rest);
  run_script(*frontend_, fmt::format("sculpt-place {} {} {}\n", world.x(), world.y(), world.z()), "place");
  EXPECT_EQ(studio().document()->version(), version);
  EXPECT_EQ(mesh_of("armrest_left").V, before.V);
  const Eigen::Vector3d center = studio().sculpt().settings().center;
  EXPECT_NEAR(center.x(), rest.x(), 1e-9);  // on the side face
  EXPECT_LT((center - rest).norm(), 5e-3) << center.transpose();  // where the mouse was, to a pixel
}

/// A slab and, above it, a small ball: pushed into the slab, the ball's vertices pass through
/// the slab's top face, whose corners are beyond the tool's reach (it does not bend).
geometry::Mesh slab_and_ball() {
  geometry::Mesh mesh = geometry::make_box({0.5, 0.5, 0.05});
  const geometry::Mesh ball = geometry::make_sphere(0.015, 2);
  const int n = mesh.vertex_count();
  mesh.V.conservativeResize(n + ball.vertex_count(), 3);
  mesh.V.bottomRows(ball.vertex_count()) = ball.V.rowwise() + Eigen::RowVector3d(0, 0, 0.075);
  mesh.F.conservativeResize(mesh.face_count() + ball.face_count(), 3);
  mesh.F.bottomRows(ball.face_count()) = ball.F.array() + n;
  return mesh;
}

TEST_F(StudioSculptMode, ARefusedMoveStopsTheStrokeAtItsLastGoodState) {
  look_from_the_side();
  ASSERT_TRUE(studio().execute(scene::replace_part_mesh("armrest_left", slab_and_ball())));
  const geometry::Mesh before = mesh_of("armrest_left");
  ASSERT_TRUE(geometry::find_self_intersections(before, 1).pairs.empty());
  studio().select_part(part("armrest_left"));
  run_script(*frontend_, "sculpt-mode on\nsculpt-tool sphere 0.04 0 0 0.075\n", "sculpt mode");
  studio().sculpt().settings().center = {0, 0, 0.075};  // on the ball
  // One move straight into the slab: refused, nothing changes.
  std::uint64_t version = studio().document()->version();
  run_script(*frontend_, drag_line({0, 0, -0.05}, 1), "one move");
  EXPECT_NE(studio().status().find("refused"), std::string::npos) << studio().status();
  EXPECT_EQ(studio().document()->version(), version);
  EXPECT_EQ(mesh_of("armrest_left").V, before.V);
  EXPECT_EQ(mesh_of("armrest_left").F, before.F);
  // Ten moves: the first ones bring the ball down, the one into the slab is refused and the
  // stroke stops there, as one undoable edit.
  version = studio().document()->version();
  run_script(*frontend_, drag_line({0, 0, -0.05}, 10), "ten moves");
  EXPECT_NE(studio().status().find("refused"), std::string::npos) << studio().status();
  EXPECT_GT(studio().document()->version(), version);
  const geometry::Mesh& stopped = mesh_of("armrest_left");
  EXPECT_LT(stopped.V.col(2).minCoeff() - before.V.col(2).minCoeff(), 1e-12);  // the slab did not move
  const int ball = geometry::make_sphere(0.015, 2).vertex_count();  // the last vertices (no remeshing)
  EXPECT_LT(stopped.V.bottomRows(ball).col(2).minCoeff(), before.V.bottomRows(ball).col(2).minCoeff() - 0.01);  // the ball did
  EXPECT_TRUE(geometry::find_self_intersections(stopped, 1).pairs.empty());
  ASSERT_TRUE(studio().undo());
  EXPECT_EQ(mesh_of("armrest_left").V, before.V);
  EXPECT_EQ(mesh_of("armrest_left").F, before.F);
}

TEST_F(StudioSculptMode, APartBakedAsTheToolSculptsWhereItIs) {
  // At t = 0.4 the backrest passes through the left armrest: baked as the tool, it carries the
  // armrest's vertices inside it along when dragged.
  studio().set_time(0.4);
  look_from_the_side();
  studio().select_part(part("armrest_left"));
  run_script(*frontend_, "sculpt-mode on\nsculpt-tool part backrest 0.02\n", "baked tool");
  const geometry::Mesh before = mesh_of("armrest_left");
  run_script(*frontend_, drag_line({0, 0, 0.01}, 4), "drag the backrest");
  EXPECT_NE(studio().status().find("sculpted armrest_left"), std::string::npos) << studio().status();
  EXPECT_NE(mesh_of("armrest_left").V, before.V);
  EXPECT_TRUE(geometry::find_self_intersections(mesh_of("armrest_left"), 1).pairs.empty());
  // The tool cannot be the part it sculpts.
  run_script(*frontend_, "sculpt-tool part armrest_left 0.02\n", "itself");
  EXPECT_FALSE(studio().sculpt().tool_center(studio()));  // no tool to draw or drag
  EXPECT_THROW(run_script(*frontend_, drag_line({0, 0, 0.01}, 4), "drag itself"), ScriptError);
  EXPECT_FALSE(studio().sculpt_selected_part());
  EXPECT_NE(studio().status().find("another part"), std::string::npos) << studio().status();
}

TEST_F(StudioSculptMode, KTogglesTheModeAndTheWheelScalesTheTool) {
  look_from_the_side();
  run_script(*frontend_, "key k\n", "no part");
  EXPECT_FALSE(studio().sculpt().mode());  // refused: no part selected
  studio().select_part(part("armrest_left"));
  run_script(*frontend_, "key k\nsculpt-tool sphere 0.03 0 0 0.05\n", "k");
  ASSERT_TRUE(studio().sculpt().mode());
  studio().sculpt().settings().center = {0, 0.19, 0};  // the armrest's front end
  run_script(*frontend_, drag_line({0, 0.01, 0}), "drag");
  const double before = studio().sculpt().settings().size.x();
  run_script(*frontend_, "sculpt-drag 0 0 0.001 wheel 2\n", "wheel");
  EXPECT_NEAR(studio().sculpt().settings().size.x(), before * 1.21, 1e-9);
  run_script(*frontend_, "key k\n", "k off");
  EXPECT_FALSE(studio().sculpt().mode());
}

/// `mesh` after the library's rotation stroke of `tool` by `degrees` about `axis` through its
/// center, applied directly (the closed form of Sweepers §4.3).
geometry::Mesh rotated_directly(geometry::Mesh mesh, const sculpt::Tool& tool, const Eigen::Vector3d& axis,
                                double degrees, const sculpt::StrokeOptions& options = {}) {
  Eigen::MatrixX3d no_normals(0, 3);
  const sculpt::ToolMotion turn = sculpt::ToolMotion::rotation(axis, degrees * M_PI / 180, tool.pose().translation);
  const sculpt::StrokeResult result = sculpt::sculpt_mesh({{tool, turn}}, options, mesh, no_normals);
  EXPECT_TRUE(result.applied) << result.refusal;
  return mesh;
}

TEST_F(StudioSculptMode, ARingDragTurnsTheToolAndThePartAboutTheRingsAxis) {
  look_from_the_side();  // along −x: the tool's x ring faces the camera
  studio().select_part(part("armrest_left"));
  run_script(*frontend_, "sculpt-mode on\nsculpt-tool box 0.2 0.2 0.2 0.08\nsculpt-center 0 -0.25 0\n", "sculpt mode");
  const Eigen::Vector3d center(0, -0.25, 0);
  const sculpt::Tool tool = sculpt::Tool::box(Eigen::Vector3d::Constant(0.2), center, 0.08);
  const geometry::Mesh before = mesh_of("armrest_left");
  // The rings are about the tool's own axes, drawn round its center; one is under the mouse
  // where it is drawn, none at the center.
  const std::optional<ToolRings> rings = studio().sculpt().rings(studio());
  ASSERT_TRUE(rings);
  EXPECT_TRUE(rings->axes.isApprox(Eigen::Matrix3d::Identity()));  // the armrest is not turned
  EXPECT_EQ(studio().sculpt().ring_at(studio(), *studio().viewport_point(rings->ring(0)[5])), 0);
  EXPECT_FALSE(studio().sculpt().ring_at(studio(), *studio().viewport_point(rings->center)));

  run_script(*frontend_, "sculpt-ring x 20\n", "turn");
  EXPECT_NE(studio().status().find("sculpted armrest_left"), std::string::npos) << studio().status();
  // The tool turned by the angle swept round its center on screen about its x axis (20° to
  // the mouse's precision: ImGui puts it at whole pixels, here some 70 from the center), and
  // keeps that rotation.
  const AxisAngle turned = axis_angle_of(studio().sculpt().settings().rotation);
  EXPECT_NEAR(turned.degrees, 20, 0.1);
  EXPECT_LT((turned.axis - Eigen::Vector3d::UnitX()).norm(), 1e-6);
  // The part's vertices: the library's rotation stroke by that angle, applied directly (the back
  // end's corners, in the tool, turned rigidly; the front's, out of its reach, did not move).
  const geometry::Mesh once = mesh_of("armrest_left");
  const geometry::Mesh expected = rotated_directly(before, tool, Eigen::Vector3d::UnitX(), turned.degrees);
  EXPECT_LT((once.V - expected.V).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_GT((once.V - before.V).cwiseAbs().maxCoeff(), 0.01);
  // What the viewport draws (and shades, with normals from its faces) is the turned mesh.
  EXPECT_EQ(studio().document()->part_meshes()[part("armrest_left")]->V, once.V);

  // The next drag starts turned: 30° in all.
  run_script(*frontend_, "sculpt-ring x 10 steps 3\n", "turn on");
  const AxisAngle total = axis_angle_of(studio().sculpt().settings().rotation);
  EXPECT_NEAR(total.degrees, 30, 0.2);
  EXPECT_LT((mesh_of("armrest_left").V - rotated_directly(before, tool, Eigen::Vector3d::UnitX(), total.degrees).V)
                .cwiseAbs()
                .maxCoeff(),
            1e-9);
  // Each drag is one undoable edit.
  ASSERT_TRUE(studio().undo());
  EXPECT_EQ(mesh_of("armrest_left").V, once.V);
  ASSERT_TRUE(studio().undo());
  EXPECT_EQ(mesh_of("armrest_left").V, before.V);
  // Turned the other way round.
  studio().sculpt().settings().rotation = Eigen::Quaterniond::Identity();
  run_script(*frontend_, "sculpt-ring x -15\n", "turn back");
  const AxisAngle back = axis_angle_of(studio().sculpt().settings().rotation);
  EXPECT_NEAR(back.degrees, 15, 0.1);
  EXPECT_LT((back.axis + Eigen::Vector3d::UnitX()).norm(), 1e-6);
  ASSERT_TRUE(studio().undo());
  // With the mirror plane y = 0 the front end turns the other way, as the library's mirrored
  // stroke does.
  studio().sculpt().settings().rotation = Eigen::Quaterniond::Identity();
  studio().sculpt().settings().mirror = 1;
  run_script(*frontend_, "sculpt-ring x 20\n", "mirrored");
  const AxisAngle mirrored = axis_angle_of(studio().sculpt().settings().rotation);
  sculpt::StrokeOptions mirror;
  mirror.mirror.axis = 1;
  const geometry::Mesh both = rotated_directly(before, tool, Eigen::Vector3d::UnitX(), mirrored.degrees, mirror);
  EXPECT_LT((mesh_of("armrest_left").V - both.V).cwiseAbs().maxCoeff(), 1e-9);
  const Eigen::MatrixX3d& V = mesh_of("armrest_left").V;
  for (int v = 0; v < before.vertex_count(); ++v) {
    EXPECT_GT((V.row(v) - before.V.row(v)).norm(), 0.005) << v;  // both ends turned
    const Eigen::RowVector3d image = V.row(v).cwiseProduct(Eigen::RowVector3d(1, -1, 1));
    EXPECT_LT((V.rowwise() - image).rowwise().norm().minCoeff(), 1e-9) << v;  // symmetric about y = 0
  }
}

TEST_F(StudioSculptMode, ARefusedTurnStopsTheStrokeAtItsLastGoodState) {
  // Turning the armrest's rear end round past half a turn would twist its long faces through
  // each other: a move is refused, and the stroke keeps the turn it had.
  look_from_the_side();
  studio().select_part(part("armrest_left"));
  run_script(*frontend_, "sculpt-mode on\nsculpt-tool box 0.2 0.2 0.2 0.08\nsculpt-center 0 -0.25 0\n", "sculpt mode");
  const geometry::Mesh before = mesh_of("armrest_left");
  run_script(*frontend_, "sculpt-ring x 270 steps 12\n", "too far");
  EXPECT_NE(studio().status().find("refused"), std::string::npos) << studio().status();
  EXPECT_NE(mesh_of("armrest_left").V, before.V);
  const AxisAngle kept = axis_angle_of(studio().sculpt().settings().rotation);
  EXPECT_GT(kept.degrees, 10);
  EXPECT_LT(kept.degrees, 180);
  EXPECT_TRUE(geometry::find_self_intersections(mesh_of("armrest_left"), 1).pairs.empty());
  ASSERT_TRUE(studio().undo());  // the stroke is one edit
  EXPECT_EQ(mesh_of("armrest_left").V, before.V);
}

TEST_F(StudioSculptMode, TheToolsRotationTurnsABoxToolAndItsRings) {
  look_from_the_side();
  studio().select_part(part("armrest_left"));
  // A thin box tool on the front end's upper corner (0.025, 0.19, 0.02), long along z before
  // it is turned (the lower corner, 4 cm below, would be in it), along −y after.
  run_script(*frontend_,
             "sculpt-mode on\nsculpt-tool box 0.01 0.01 0.1 0.01\nsculpt-center 0.025 0.19 0.02\n"
             "sculpt-rotation 1 0 0 90\n",
             "turned tool");
  const std::optional<ToolRings> rings = studio().sculpt().rings(studio());
  ASSERT_TRUE(rings);
  EXPECT_LT((rings->axes.col(2) - Eigen::Vector3d(0, -1, 0)).norm(), 1e-12);
  const geometry::Mesh before = mesh_of("armrest_left");
  int upper = -1, lower = -1;
  for (int v = 0; v < before.vertex_count(); ++v) {
    if ((before.V.row(v) - Eigen::RowVector3d(0.025, 0.19, 0.02)).norm() < 1e-12) upper = v;
    if ((before.V.row(v) - Eigen::RowVector3d(0.025, 0.19, -0.02)).norm() < 1e-12) lower = v;
  }
  ASSERT_GE(upper, 0);
  ASSERT_GE(lower, 0);
  run_script(*frontend_, drag_line({0, 0, 0.01}, 4), "drag");
  const Eigen::Vector3d moved = studio().sculpt().settings().center - Eigen::Vector3d(0.025, 0.19, 0.02);
  EXPECT_GT(moved.norm(), 0.005);
  const geometry::Mesh& after = mesh_of("armrest_left");
  EXPECT_LT((after.V.row(upper) - before.V.row(upper) - moved.transpose()).norm(), 1e-12);  // in the tool
  EXPECT_EQ(after.V.row(lower), before.V.row(lower));  // beyond the turned tool's coating
  // The rotation stays for the next stroke.
  const AxisAngle kept = axis_angle_of(studio().sculpt().settings().rotation);
  EXPECT_NEAR(kept.degrees, 90, 1e-9);
  EXPECT_LT((kept.axis - Eigen::Vector3d::UnitX()).norm(), 1e-9);
  EXPECT_THROW(run_script(*frontend_, "sculpt-rotation 0 0 0 30\n", "zero axis"), ScriptError);
  EXPECT_THROW(run_script(*frontend_, "sculpt-ring w 30\n", "no such ring"), ScriptError);
}

}  // namespace
}  // namespace reconfig::studio
