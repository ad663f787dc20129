// Authoring a design in the studio, driven by scripts headless: every authoring action, its
// undo and its redo; bad input in the dialogs as status messages with the design untouched; a
// new design saved with relative mesh paths; and the bench-table built from its meshes alone,
// in which detection finds what it finds in the shipped scene.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "reconfig/collision/detect_collisions.h"
#include "reconfig/scene/scene_file.h"
#include "script.h"
#include "studio_test_util.h"

namespace reconfig::studio {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

class StudioAuthoring : public ::testing::Test {
 protected:
  void SetUp() override {
    StudioOptions options;
    options.autosave_interval = milliseconds(60000);
    frontend_ = std::make_unique<HeadlessFrontend>(1000, 700, options);
    frontend_->run_frame();
  }

  Studio& studio() { return frontend_->studio(); }
  const scene::Reconfigurable& design() { return studio().document()->scene(); }
  void run(const std::string& script) { run_script(*frontend_, script, "test"); }
  void open_bench() {
    ASSERT_TRUE(studio().open(bench_table_copy())) << studio().status();
    frontend_->run_frame();
  }
  static std::string meshes() { return (testing::source_dir() / "examples/bench-table/meshes").string(); }

  std::unique_ptr<HeadlessFrontend> frontend_;
};

/// `edit`, then checks `after` holds; undo, `before` holds; redo, `after` again; undo again,
/// so the next edit starts from the design as it was.
std::string undo_redo(const std::string& edit, const std::string& before, const std::string& after) {
  return fmt::format("{1}\n{0}\n{2}\nundo\n{1}\nredo\n{2}\nundo\n{1}\n", edit, before, after);
}

TEST_F(StudioAuthoring, PartCommandsUndoAndRedo) {
  open_bench();
  run("add-primitive lid cylinder 0.1 0.02\nexpect-selected lid\nundo");
  run(undo_redo("add-primitive lid cylinder 0.1 0.02", "expect-no-name part lid\nexpect-count parts 6",
                "expect-name part lid\nexpect-count parts 7"));
  run(undo_redo("rename-part seat bench_seat", "expect-name part seat\nexpect-no-name part bench_seat",
                "expect-name part bench_seat\nexpect-no-name part seat"));
  run(undo_redo("duplicate-part seat seat_copy", "expect-count parts 6", "expect-name part seat_copy"));
  run(undo_redo("delete-part armrest_left", "expect-name part armrest_left", "expect-no-name part armrest_left"));
  run("expect-refused delete-part backrest\nexpect-status moves in transitions \"unfold\", \"unfold_lifted\"");
  run(undo_redo("delete-part backrest with-keys", "expect-name part backrest\nexpect-count parts 6",
                "expect-no-name part backrest\nexpect-count parts 5"));
  run("recolor seat 1 0 0");
  EXPECT_EQ(*design().parts[design().find_part("seat")].color, Eigen::Vector3d(1, 0, 0));
  run("undo");
  EXPECT_EQ(*design().parts[design().find_part("seat")].color, Eigen::Vector3d(0.72, 0.52, 0.32));
  const int backrest = design().find_part("backrest");
  const int plain = design().parts[backrest].mesh.vertex_count();
  const Eigen::Vector3d pivot = design().parts[backrest].center;
  run(fmt::format("replace-mesh backrest {}/backrest-carved.obj", meshes()));
  EXPECT_NE(design().parts[backrest].mesh.vertex_count(), plain);
  EXPECT_EQ(design().parts[backrest].center, pivot);
  run("undo");
  EXPECT_EQ(design().parts[backrest].mesh.vertex_count(), plain);
}

TEST_F(StudioAuthoring, StateCommandsUndoAndRedo) {
  open_bench();
  run(undo_redo("scrub 0.5\nadd-state halfway", "expect-count states 2", "expect-name state halfway\nexpect-count states 3"));
  // The new state holds the poses shown when it was added: halfway through unfold.
  run("open-transition unfold\nscrub 0.5\nadd-state middle");
  const double t = studio().time();
  EXPECT_NEAR(t, 0.5, 0.01);
  const auto& unfold_pose = design().pose_at(design().find_transition("unfold"), design().find_part("backrest"), t);
  EXPECT_EQ(design().states.back().pose_of("backrest").translation, unfold_pose.translation);
  run(undo_redo("rename-state bench couch", "expect-name state bench", "expect-name state couch"));
  run("rename-state bench couch");
  EXPECT_EQ(design().transitions[0].from, "couch");
  run("undo");
  run("expect-refused delete-state table\nexpect-status end of transitions");
  run(undo_redo("delete-state table with-transitions", "expect-count transitions 2\nexpect-name state table",
                "expect-count transitions 0\nexpect-no-name state table"));
  run(undo_redo("delete-state middle", "expect-name state middle", "expect-no-name state middle"));
}

TEST_F(StudioAuthoring, TransitionCommandsUndoAndRedo) {
  open_bench();
  run("add-transition fold table bench screw\nexpect-transition fold\nundo");
  run(undo_redo("add-transition fold table bench screw", "expect-count transitions 2", "expect-name transition fold"));
  run(undo_redo("rename-transition unfold open_up", "expect-name transition unfold", "expect-name transition open_up"));
  run(undo_redo("reverse-transition unfold", "", ""));
  run("reverse-transition unfold");
  EXPECT_EQ(design().transitions[0].from, "table");
  run("undo");
  EXPECT_EQ(design().transitions[0].from, "bench");
  run(undo_redo("duplicate-transition unfold unfold_again", "expect-count transitions 2",
                "expect-count transitions 3\nexpect-name transition unfold_again"));
  run(undo_redo("delete-transition unfold_lifted", "expect-name transition unfold_lifted",
                "expect-no-name transition unfold_lifted"));
  // Dragging from a node to another in the state graph adds a transition between them.
  run("drag-state table bench\nexpect-transition table_to_bench\nundo");
  run(undo_redo("drag-state table bench", "expect-count transitions 2", "expect-name transition table_to_bench"));
}

TEST_F(StudioAuthoring, DetectionFollowsTheEdits) {
  open_bench();
  run("wait-collisions\nopen-transition unfold\nexpect-collisions 2\n"
      "delete-part armrest_left\nwait-collisions\nexpect-collisions 1\n"
      "undo\nwait-collisions\nexpect-collisions 2\n"
      "reverse-transition unfold\nwait-collisions\nexpect-collisions 2\n"
      "add-transition fold table bench\nwait-collisions\nexpect-transition fold\nexpect-collisions 2\n");
}

TEST_F(StudioAuthoring, BadInputIsAStatusMessageAndTheDesignIsUntouched) {
  run("expect-refused import /no/such/mesh.obj\nexpect-status start a design");
  open_bench();
  const fs::path dir = studio().document()->file().parent_path();
  std::ofstream(dir / "points.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  std::ofstream(dir / "fan.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0 -1 0\nf 1 2 3\nf 1 2 4\nf 1 2 5\n";
  run("expect-refused import /no/such/mesh.obj\nexpect-status cannot import /no/such/mesh.obj");
  run(fmt::format("expect-refused import {}\nexpect-status no triangles", (dir / "points.obj").string()));
  run(fmt::format("expect-refused import {}\nexpect-status non-manifold", (dir / "fan.obj").string()));
  run(fmt::format("expect-refused import {}/seat.obj /no/such/mesh.obj\nexpect-count parts 6", meshes()));
  run("expect-refused replace-mesh seat /no/such/mesh.obj\nexpect-status cannot replace the mesh");
  run("expect-refused add-primitive seat box 1 1 1\nexpect-status already a part named \"seat\"");
  run("expect-refused add-primitive flat box 1 0 1\nexpect-status sizes must be positive");
  run("expect-refused rename-part seat backrest\nexpect-status already a part named");
  run("expect-refused rename-part nobody x\nexpect-status unknown part");
  run("expect-refused add-state bench\nexpect-status already a state named");
  run("expect-refused add-transition unfold bench table\nexpect-status already a transition named");
  run("expect-refused recolor seat 2 0 0\nexpect-status [0, 1]");
  run(fmt::format("expect-refused new {}\nexpect-status exists already", studio().document()->file().string()));
  EXPECT_FALSE(studio().document()->modified());
}

TEST_F(StudioAuthoring, OpenMeshesAreImportedWithAWarning) {
  const fs::path dir = testing::fresh_temp_dir();
  std::ofstream(dir / "open.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n";
  run(fmt::format("new {0}/design.json\nimport {0}/open.obj\nexpect-name part open\nexpect-status warning: open: open",
                  dir.string()));
}

TEST_F(StudioAuthoring, AGltfWithTwoMeshesGivesTwoPartsInOneStep) {
  const fs::path dir = testing::fresh_temp_dir();
  run(fmt::format("new {}/design.json\nimport {}\nexpect-count parts 2\nexpect-name part small_tet\n"
                  "expect-name part big_tet\nundo\nexpect-count parts 0\nredo\nexpect-count parts 2\nsave",
                  dir.string(), (testing::source_dir() / "tests/data/two_tetrahedra.gltf").string()));
  // Neither mesh has a file of its own: saving wrote both beside the design.
  const scene::Reconfigurable saved = scene::load_scene(dir / "design.json");
  ASSERT_EQ(saved.parts.size(), 2u);
  EXPECT_EQ(std::get<scene::MeshFile>(saved.parts[1].source).path, (dir / "meshes" / "big_tet.obj").lexically_normal());
  EXPECT_NEAR(saved.parts[1].mesh.V.col(0).maxCoeff(), 4, 1e-6);
}

TEST_F(StudioAuthoring, ANewDesignIsSavedWithMeshPathsRelativeToIt) {
  const fs::path dir = testing::fresh_temp_dir() / "lamp";
  fs::create_directories(dir / "meshes");
  fs::copy(testing::source_dir() / "examples/bench-table/meshes/seat.obj", dir / "meshes/seat.obj");
  run(fmt::format("new {0}/lamp.json\nimport {0}/meshes/seat.obj\nadd-primitive post cylinder 0.03 0.6\n"
                  "set-pose start post 2 0 0.2\nadd-state lowered\nset-pose lowered post 2 0 -0.2\n"
                  "add-transition lower start lowered\nwait-collisions\nexpect-collisions 0\nsave",
                  dir.string()));
  std::ifstream in(dir / "lamp.json");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("\"mesh\": \"meshes/seat.obj\""), std::string::npos) << text.str();
  const scene::Reconfigurable saved = scene::load_scene(dir / "lamp.json");
  EXPECT_EQ(saved.parts.size(), 2u);
  EXPECT_EQ(saved.transitions.size(), 1u);
  EXPECT_EQ(saved.transitions[0].tracks.count("post"), 1u);
}

/// The collision intervals of every transition: (transition, t0, t1, parts).
std::vector<std::tuple<int, double, double, std::vector<int>>> intervals_of(const scene::Reconfigurable& design) {
  std::vector<std::tuple<int, double, double, std::vector<int>>> all;
  const collision::CollisionResult result = collision::detect_collisions(design);
  for (std::size_t t = 0; t < result.transitions.size(); ++t)
    for (const auto& interval : result.transitions[t].intervals)
      all.emplace_back(static_cast<int>(t), interval.t0, interval.t1, interval.parts);
  return all;
}

TEST_F(StudioAuthoring, TheBenchBuiltFromItsMeshesHasTheShippedCollisions) {
  std::ifstream in(testing::source_dir() / "examples/bench-table/build-from-meshes.txt");
  std::stringstream text;
  text << in.rdbuf();
  std::string script = text.str();
  const fs::path dir = testing::fresh_temp_dir();
  // Where the script saves (out/…) and reads (examples/…), from this test's folders.
  const auto replace_all = [&](const std::string& from, const std::string& to) {
    for (std::size_t at = 0; (at = script.find(from, at)) != std::string::npos; at += to.size()) script.replace(at, from.size(), to);
  };
  replace_all("out/bench-built/", dir.string() + "/");
  replace_all("examples/", (testing::source_dir() / "examples").string() + "/");
  run_script(*frontend_, script, "build-from-meshes.txt");
  scene::SceneLoadOptions outside;
  outside.allow_outside_paths = true;  // its meshes are the example's
  const scene::Reconfigurable built = scene::load_scene(dir / "scene.json", outside);
  const scene::Reconfigurable shipped = scene::load_scene(testing::source_dir() / "examples/bench-table/scene.json");
  const auto expected = intervals_of(shipped), found = intervals_of(built);
  ASSERT_EQ(expected.size(), 2u);  // the backrest hits both armrests in unfold
  ASSERT_EQ(found.size(), expected.size());
  for (std::size_t k = 0; k < found.size(); ++k) {
    EXPECT_EQ(std::get<0>(found[k]), std::get<0>(expected[k]));
    EXPECT_NEAR(std::get<1>(found[k]), std::get<1>(expected[k]), 1e-9);
    EXPECT_NEAR(std::get<2>(found[k]), std::get<2>(expected[k]), 1e-9);
    EXPECT_EQ(std::get<3>(found[k]), std::get<3>(expected[k]));
  }
}

}  // namespace
}  // namespace reconfig::studio
