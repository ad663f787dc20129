// The linkage panel, driven headless by script lines as a user drags: a joint drag on the
// walker's Jansen leg keeps the crank turning fully and the foot on its curve as closely as
// `reconfig linkage edit` does, the driven plates follow the new linkage, undo restores;
// curve targets and the enclosure; bad files and drags that would break the drive are
// refused with a message and change nothing.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <numbers>
#include <fstream>
#include <regex>
#include <sstream>

#include "reconfig/linkage/joint_order.h"
#include "reconfig/linkage/linkage_edit.h"
#include "reconfig/linkage/linkage_file.h"
#include "reconfig/linkage/motion_range.h"
#include "reconfig/scene/linkage_drive.h"
#include "script.h"
#include "studio_test_util.h"
#include "support/run_command.h"

namespace reconfig::studio {
namespace {

using std::chrono::milliseconds;
namespace fs = std::filesystem;

fs::path examples_copy() {
  const fs::path dir = testing::fresh_temp_dir() / "examples";
  fs::create_directories(dir);
  for (const char* example : {"linkage-walker", "linkages"})
    fs::copy(testing::source_dir() / "examples" / example, dir / example, fs::copy_options::recursive);
  return dir;
}

class LinkagePanelTest : public ::testing::Test {
 protected:
  void SetUp() override {
    StudioOptions options;
    options.autosave_interval = milliseconds(0);
    frontend_ = std::make_unique<HeadlessFrontend>(1280, 800, options);
    examples_ = examples_copy();
  }

  Studio& studio() { return frontend_->studio(); }
  void script(const std::string& text) { run_script(*frontend_, text, "test"); }
  const scene::Reconfigurable& design() { return studio().document()->scene(); }
  const scene::LinkageDrive& drive(const std::string& transition) {
    return *design().transitions[design().find_transition(transition)].linkage;
  }

  std::unique_ptr<HeadlessFrontend> frontend_;
  fs::path examples_;
};

/// The largest deviation `reconfig linkage edit` reports for the kept trajectory of `point`.
double cli_deviation(const std::string& arguments, const std::string& point) {
  const testing::CommandResult r = testing::run_reconfig("linkage edit " + arguments);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  std::smatch match;
  EXPECT_TRUE(std::regex_search(r.out, match, std::regex("trajectory of " + point + ": largest deviation ([0-9.e+-]+)")))
      << r.out;
  return match.empty() ? 0 : std::stod(match[1]);
}

double rotation_angle(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) { return a.angularDistance(b); }

TEST_F(LinkagePanelTest, AJointDragOnTheJansenLegKeepsItWorkingMovesThePlatesAndUndoes) {
  ASSERT_TRUE(studio().open(examples_ / "linkage-walker" / "scene.json")) << studio().status();
  frontend_->run_frame();
  ASSERT_TRUE(studio().linkage_panel().shown());  // the first transition has a drive
  const linkage::Linkage original = drive("walk").linkage;
  const int walk = design().find_transition("walk");
  const std::vector<double> times = {0.0, 0.2, 0.45, 0.7, 0.95};
  std::vector<motion::Pose> before;
  for (const auto& a : drive("walk").attach)
    for (double t : times) before.push_back(design().pose_at(walk, design().find_part(a.part), t));

  // U dragged towards (−30, 35), as `reconfig linkage edit --drag U -30 35 --keep-trajectory foot`.
  script("linkage-drag-joint walk U -5.98646490287221 3.72790254515732 keep=foot\n");
  ASSERT_NE(studio().status().find("drag joint U of walk"), std::string::npos) << studio().status();
  const linkage::Linkage& edited = drive("walk").linkage;
  ASSERT_NE(edited.initial_positions(), original.initial_positions());
  EXPECT_FALSE(drive("walk").file.has_value());  // saved inline; the shared jansen.json stays
  EXPECT_EQ(drive("walk_flat").linkage.initial_positions(), original.initial_positions());
  ASSERT_TRUE(studio().linkage_panel().last_drag());
  const Eigen::Vector2d target = studio().linkage_panel().last_drag()->second;
  EXPECT_LT((target - Eigen::Vector2d(-30, 35)).norm(), 0.5);  // the mouse moves in whole pixels
  EXPECT_LT((edited.joints[edited.find_joint("U")].position - target).norm(),
            (original.joints[original.find_joint("U")].position - target).norm() / 10);

  // The crank still turns fully and the foot stays on its curve as well as the CLI keeps it.
  script("linkage-expect-motion full\n");
  const LinkagePanel& panel = studio().linkage_panel();
  const double studio_deviation =
      LinkageEditor::deviation(edited, 0, panel.opened_angles(), panel.opened_curves()[0]);
  const double cli = cli_deviation(fmt::format("{} --drag U {:.17g} {:.17g} --keep-trajectory foot -o {}",
                                               (testing::source_dir() / "examples/linkages/jansen.json").string(),
                                               target.x(), target.y(), (testing::fresh_temp_dir() / "e.json").string()),
                                   "P");
  EXPECT_GT(cli, 0);
  // (The CLI prints 6 significant digits.)
  EXPECT_LE(studio_deviation, cli * (1 + 1e-5)) << "studio " << studio_deviation << ", CLI " << cli;
  script(fmt::format("linkage-expect-deviation foot {}\n", cli * (1 + 1e-5)));

  // The plates follow the new linkage (the compiled tracks against the exact drive poses), and
  // have moved.
  double moved = 0;
  std::size_t k = 0;
  for (const auto& a : drive("walk").attach) {
    const int part = design().find_part(a.part);
    const std::vector<motion::Pose> exact = scene::linkage_drive_poses(design(), walk, part, times);
    for (std::size_t i = 0; i < times.size(); ++i, ++k) {
      const motion::Pose now = design().pose_at(walk, part, times[i]);
      EXPECT_LT((now.translation - exact[i].translation).norm(), drive("walk").tolerance) << a.part << " " << times[i];
      EXPECT_LT(rotation_angle(now.rotation, exact[i].rotation), 1e-3) << a.part << " " << times[i];
      moved = std::max(moved, (now.translation - before[k].translation).norm());
    }
  }
  EXPECT_GT(moved, 0.01);  // metres: the leg changed shape by centimetres

  // Their collisions are detected again for the new version.
  ASSERT_TRUE(frontend_->run_until_collisions_current(milliseconds(60000)));
  EXPECT_EQ(studio().collisions()->version, studio().document()->version());

  script("key ctrl+z\nexpect-status undid drag joint U of walk\n");
  EXPECT_EQ(drive("walk").linkage.initial_positions(), original.initial_positions());
  k = 0;
  for (const auto& a : drive("walk").attach)
    for (double t : times) {
      const motion::Pose now = design().pose_at(walk, design().find_part(a.part), t);
      EXPECT_EQ(now.translation, before[k].translation);
      EXPECT_EQ(now.rotation.coeffs(), before[k++].rotation.coeffs());
    }
  // The panel shows the linkage as it is again.
  EXPECT_EQ(studio().linkage_panel().editor().linkage().initial_positions(), original.initial_positions());
}

TEST_F(LinkagePanelTest, TheWalkersLinkageSessionReplays) {
  ASSERT_TRUE(studio().open(examples_ / "linkage-walker" / "scene.json")) << studio().status();
  std::ifstream in(testing::source_dir() / "examples/linkage-walker/studio-linkage-session.txt");
  std::stringstream text;
  text << in.rdbuf();
  ASSERT_FALSE(text.str().empty());
  EXPECT_NO_THROW(run_script(*frontend_, text.str(), "studio-linkage-session.txt"));
  EXPECT_NE(drive("walk").linkage.initial_positions(),
            linkage::read_linkage(examples_ / "linkages" / "jansen.json").initial_positions());  // redone
}

TEST_F(LinkagePanelTest, SavingAnEditedDriveWritesItInlineAndReopensTheSame) {
  ASSERT_TRUE(studio().open(examples_ / "linkage-walker" / "scene.json")) << studio().status();
  script("linkage-drag-joint walk E -6 4 keep=foot\n");
  const linkage::Linkage edited = drive("walk").linkage;
  const fs::path saved = examples_ / "linkage-walker" / "edited.json";
  ASSERT_TRUE(studio().save_as(saved)) << studio().status();
  ASSERT_TRUE(studio().open(saved)) << studio().status();
  EXPECT_EQ(drive("walk").linkage.initial_positions(), edited.initial_positions());
  EXPECT_EQ(linkage::read_linkage(examples_ / "linkages" / "jansen.json").initial_positions(),
            drive("walk_flat").linkage.initial_positions());
}

TEST_F(LinkagePanelTest, ALinkageOpenedAloneIsEditedUndoneAndSaved) {
  const fs::path file = examples_ / "linkages" / "jansen.json";
  ASSERT_TRUE(studio().open(file)) << studio().status();
  ASSERT_TRUE(studio().linkage_panel().lone());
  EXPECT_EQ(studio().document(), nullptr);
  const linkage::Linkage original = linkage::read_linkage(file);
  script("linkage-drag-joint - U -6 4 keep=foot\nlinkage-expect-motion full\nlinkage-expect-deviation foot 0.5\n");
  const linkage::Linkage edited = studio().linkage_panel().editor().linkage();
  ASSERT_NE(edited.initial_positions(), original.initial_positions());
  script("key ctrl+z\nexpect-status undid the linkage edit\n");
  EXPECT_EQ(studio().linkage_panel().editor().linkage().initial_positions(), original.initial_positions());
  script("key ctrl+shift+z\n");
  EXPECT_EQ(studio().linkage_panel().editor().linkage().initial_positions(), edited.initial_positions());
  const fs::path saved = examples_ / "edited-jansen.json";
  script("save " + saved.string() + "\n");
  EXPECT_EQ(linkage::read_linkage(saved).initial_positions(), edited.initial_positions());
}

TEST_F(LinkagePanelTest, UnsavedEditsOfALinkageOpenedAloneAreNeverDroppedSilently) {
  ASSERT_TRUE(studio().open(examples_ / "linkages" / "jansen.json")) << studio().status();
  script("linkage-drag-joint - U -6 4 keep=foot\n");
  ASSERT_TRUE(studio().linkage_panel().lone_modified());
  const auto edited = studio().linkage_panel().editor().linkage().initial_positions();
  EXPECT_FALSE(studio().open(examples_ / "linkage-walker" / "scene.json"));
  EXPECT_NE(studio().status().find("unsaved edits"), std::string::npos) << studio().status();
  EXPECT_FALSE(studio().new_design(examples_ / "new.scene.json"));
  EXPECT_EQ(studio().linkage_panel().editor().linkage().initial_positions(), edited);
  studio().request_close();  // asks instead of quitting
  frontend_->run_frame();
  EXPECT_FALSE(studio().quit_requested());
  studio().linkage_panel().close_unless_unsaved(studio());
  EXPECT_TRUE(studio().linkage_panel().lone()) << "the first Close only warns";
  studio().linkage_panel().close_unless_unsaved(studio());
  EXPECT_FALSE(studio().linkage_panel().lone());
  EXPECT_TRUE(studio().open(examples_ / "linkage-walker" / "scene.json")) << studio().status();
}

TEST_F(LinkagePanelTest, ATargetCurveDragBendsTheFootPathTowardIt) {
  ASSERT_TRUE(studio().open(examples_ / "linkages" / "jansen.json")) << studio().status();
  // The lowest sample of the foot curve lifted by 8 with a soft selection of radius 15.
  const auto& foot = studio().linkage_panel().editor().curve(0);
  int lowest = 0;
  for (int s = 0; s < static_cast<int>(foot.size()); ++s)
    if (foot[s].y() < foot[lowest].y()) lowest = s;
  script(fmt::format("linkage-drag-curve - foot {} 0 8 radius=15\n", lowest));
  ASSERT_NE(studio().status().find("bend the curve of foot"), std::string::npos) << studio().status();
  const LinkageEditor& editor = studio().linkage_panel().editor();
  ASSERT_TRUE(editor.targets[0]);
  // The target (resampled at the sample angles of the edited linkage) against the foot's
  // motion before and after the fit.
  const auto& target = *editor.targets[0];
  const std::vector<Eigen::Vector2d> unedited =
      linkage::joint_trajectory(linkage::read_linkage(examples_ / "linkages" / "jansen.json"),
                                editor.linkage().tracking_points[0].joint, editor.sample_angles());
  double before = 0;
  for (std::size_t s = 0; s < target.size(); ++s) before = std::max(before, (unedited[s] - target[s]).norm());
  EXPECT_NEAR(before, 8, 0.5);  // whole pixels, and the peak between two samples
  const double after = LinkageEditor::deviation(editor.linkage(), 0, editor.sample_angles(), target);
  EXPECT_LT(after, 0.5 * before) << before << " -> " << after;
  script("linkage-expect-motion full\n");
}

TEST_F(LinkagePanelTest, TheEnclosurePullsTheJointsIn) {
  ASSERT_TRUE(studio().open(examples_ / "linkages" / "jansen.json")) << studio().status();
  const auto outside = [&](const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
    const LinkageEditor& editor = studio().linkage_panel().editor();
    double worst = 0;
    Eigen::Matrix2Xd X;
    for (double angle : editor.sample_angles()) {
      EXPECT_TRUE(editor.solve(angle, X));
      for (Eigen::Index j = 0; j < X.cols(); ++j)
        worst = std::max({worst, (lo - X.col(j)).maxCoeff(), (X.col(j) - hi).maxCoeff()});
    }
    return worst;
  };
  const Eigen::Vector2d lo(-80, -95), hi(10, 40);  // the crank reaches x = 15, E x = −75…−80
  const double before = outside(lo, hi);
  ASSERT_GT(before, 3);
  script("linkage-enclosure - -80 -95 10 40\nlinkage-expect-motion full\n");
  EXPECT_LT(outside(lo, hi), before / 2);
}

TEST_F(LinkagePanelTest, BadLinkageFilesAreMessagesAndChangeNothing) {
  ASSERT_TRUE(studio().open(examples_ / "linkage-walker" / "scene.json")) << studio().status();
  frontend_->run_frame();
  const std::uint64_t version = studio().document()->version();
  const fs::path bad = examples_ / "bad.json";
  std::ofstream(bad) << R"({"format": "reconfig-linkage", "version": 1, "joints": [{"name": "O", "position": [0, 0],
    "fixed": true}, {"name": "C", "position": [1, 0]}], "links": [["O", "Q"]], "motor": {"center": "O", "joint": "C"}})";
  EXPECT_FALSE(studio().open(bad));
  EXPECT_NE(studio().status().find("bad.json"), std::string::npos) << studio().status();
  EXPECT_NE(studio().status().find("links[0][1]"), std::string::npos) << studio().status();
  const fs::path broken = examples_ / "broken.json";
  std::ofstream(broken) << R"({"format": "reconfig-linkage", "joints": [)";
  EXPECT_FALSE(studio().linkage_panel().open_file(studio(), broken));
  EXPECT_NE(studio().status().find("broken.json"), std::string::npos) << studio().status();
  EXPECT_FALSE(studio().linkage_panel().open_file(studio(), examples_ / "missing.json"));
  EXPECT_NE(studio().status().find("missing.json"), std::string::npos) << studio().status();
  frontend_->run_frame();
  EXPECT_EQ(studio().document()->version(), version);
  EXPECT_FALSE(studio().linkage_panel().lone());
  EXPECT_EQ(studio().linkage_panel().transition(studio()), design().find_transition("walk"));
  EXPECT_THROW(script("linkage-drag-joint walk Z 1 1\n"), ScriptError);
  EXPECT_THROW(script("linkage-drag-joint walk U 1 x\n"), ScriptError);
  EXPECT_EQ(studio().document()->version(), version);
}

/// A scene where two transitions swing a bar on the Peaucellier–Lipkin inversor's crank from
/// state "low" to "high", both driven by the same linkage file.
fs::path twin_swing_scene(const fs::path& dir) {
  std::ofstream(dir / "bar.obj") << "v 0 -0.05 -0.05\nv 1 -0.05 -0.05\nv 1 0.05 -0.05\nv 0 0.05 -0.05\n"
                                    "v 0 -0.05 0.05\nv 1 -0.05 0.05\nv 1 0.05 0.05\nv 0 0.05 0.05\n"
                                    "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\n"
                                    "f 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";
  const std::string drive = R"("linkage": {"file": "linkages/peaucellier_lipkin.json", "motor": {"from": -60, "to": 60},
      "attach": [{"part": "bar", "link": ["Q", "A"]}]})";
  const fs::path scene = dir / "swing.json";
  std::ofstream(scene) << R"({"format": "reconfig-scene", "version": 1, "units": "m",
    "parts": [{"name": "bar", "mesh": "bar.obj"}],
    "states": [{"name": "low", "poses": {}}, {"name": "high", "poses": {}}],
    "transitions": [{"name": "swing", "from": "low", "to": "high", )" << drive << R"(},
                    {"name": "swing_again", "from": "low", "to": "high", )" << drive << "}]}";
  return scene;
}

TEST_F(LinkagePanelTest, ADragTheDesignCannotTakeIsRefusedAndChangesNothing) {
  ASSERT_TRUE(studio().open(twin_swing_scene(examples_))) << studio().status();
  frontend_->run_frame();
  ASSERT_TRUE(studio().linkage_panel().shown());
  script("linkage-expect-motion rocks\n");  // the panel shows it in red, and the status line
  EXPECT_NE(studio().status().find("the linkage of swing: crank cannot turn fully: range [-82.8°, 82.8°]"),
            std::string::npos)
      << studio().status();
  const std::uint64_t version = studio().document()->version();
  const linkage::Linkage original = drive("swing").linkage;
  // Moving the crank's pivot Q moves the bar in the end states, where the other transition,
  // driven by the unedited linkage, puts it elsewhere.
  script("linkage-drag-joint swing Q 0.3 0 keep=tracer\n");
  EXPECT_NE(studio().status().find("drag joint Q of swing: refused"), std::string::npos) << studio().status();
  EXPECT_NE(studio().status().find("does not match the pose of part \"bar\" in state \"low\""), std::string::npos) << studio().status();
  EXPECT_EQ(studio().document()->version(), version);
  EXPECT_EQ(drive("swing").linkage.initial_positions(), original.initial_positions());
  EXPECT_EQ(studio().linkage_panel().editor().linkage().initial_positions(), original.initial_positions());
}

TEST(LinkageEditorTest, EditsThatNarrowTheMotorIntervalAreRefused) {
  LinkageEditor editor;
  editor.set_linkage(linkage::read_linkage(testing::source_dir() / "examples/linkages/peaucellier_lipkin.json"));
  const linkage::MotionRange range = editor.range();
  ASSERT_FALSE(range.full_rotation);
  EXPECT_NE(editor.motion_problem().find("crank cannot turn fully: range [-82.8°, 82.8°]"), std::string::npos)
      << editor.motion_problem();
  // The drive asks for all but a hair of the range: an edit must not narrow it.
  editor.motor_interval = std::pair{range.lower + 1e-6, range.upper - 1e-6};
  editor.keep = {true};
  int refused = 0, offered = 0;
  const linkage::Linkage& mechanism = editor.linkage();
  for (int joint = 0; joint < static_cast<int>(mechanism.joints.size()); ++joint)
    for (const Eigen::Vector2d& offset : {Eigen::Vector2d(0.3, 0), Eigen::Vector2d(-0.3, 0), Eigen::Vector2d(0, 0.3)}) {
      const LinkageEditOutcome outcome =
          editor.drag_joint(joint, mechanism.joints[joint].position + offset, editor.initial_angle());
      const linkage::MotionRange after = linkage::motion_range(
          linkage::SymbolicKinematics(outcome.result.linkage, linkage::order_joints(outcome.result.linkage)));
      if (outcome.refusal.empty()) {
        ++offered;
        EXPECT_TRUE(after.contains(range.lower + 1e-6) && after.contains(range.upper - 1e-6));
      } else if (outcome.refusal.find("the motor cannot turn") != std::string::npos) {
        ++refused;
        EXPECT_FALSE(after.contains(range.lower + 1e-6) && after.contains(range.upper - 1e-6));
      }
    }
  EXPECT_GT(refused, 0);
  EXPECT_GT(offered, 0);
}

TEST(LinkageEditorTest, ResampledCurvesFollowTheAngle) {
  // A circle traced at angle a: resampling at shifted angles is exact at the samples and
  // within the chord error between them.
  const int n = 72;
  std::vector<double> from, to;
  std::vector<Eigen::Vector2d> circle;
  for (int s = 0; s < n; ++s) {
    from.push_back(0.3 + 2 * std::numbers::pi * s / n);
    circle.push_back({std::cos(from.back()), std::sin(from.back())});
  }
  for (int s = 0; s < 500; ++s) to.push_back(-7 + 0.037 * s);
  const auto periodic = resample_curve(circle, from, to, true);
  const double chord = 1 - std::cos(std::numbers::pi / n);
  for (std::size_t s = 0; s < to.size(); ++s)
    EXPECT_LE((periodic[s] - Eigen::Vector2d(std::cos(to[s]), std::sin(to[s]))).norm(), chord + 1e-12) << to[s];
  EXPECT_EQ(resample_curve(circle, from, from, true), circle);
  EXPECT_EQ(resample_curve(circle, from, from, false), circle);
  const auto clamped = resample_curve(circle, from, {-1.0, 100.0}, false);
  EXPECT_EQ(clamped[0], circle.front());
  EXPECT_EQ(clamped[1], circle.back());
}

TEST(LinkageEditorTest, FlippedTrianglesNameTheJointsOnTheOtherBranch) {
  const linkage::Linkage jansen = linkage::read_linkage(testing::source_dir() / "examples/linkages/jansen.json");
  const linkage::JointOrder order = linkage::order_joints(jansen);
  const Eigen::Matrix2Xd X = jansen.initial_positions();
  EXPECT_TRUE(flipped_triangles(order, X, X).empty());
  for (const linkage::Rule& rule : order.rules) {
    if (rule.kind != linkage::RuleKind::kTriangle) continue;
    // Mirror k across the line through i and j: the same lengths, the other branch.
    Eigen::Matrix2Xd Y = X;
    const Eigen::Vector2d a = X.col(rule.i), u = (X.col(rule.j) - a).normalized(), r = X.col(rule.k) - a;
    Y.col(rule.k) = a + 2 * r.dot(u) * u - r;
    const std::vector<int> flipped = flipped_triangles(order, X, Y);
    ASSERT_FALSE(flipped.empty()) << jansen.joints[rule.k].name;
    EXPECT_EQ(flipped.front(), rule.k);
  }
}

TEST(LinkageEditorTest, AnEditWithNothingToDoIsRefused) {
  LinkageEditor editor;
  editor.set_linkage(linkage::read_linkage(testing::source_dir() / "examples/linkages/jansen.json"));
  EXPECT_NE(editor.fit().refusal.find("nothing to edit"), std::string::npos);
}

}  // namespace
}  // namespace reconfig::studio
