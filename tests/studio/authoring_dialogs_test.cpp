// The authoring dialogs: each draws (headless) without trouble, and bad input in it — a
// missing file, a mesh with no triangles, a duplicate name — is a message in the status bar,
// the design untouched.

#include <gtest/gtest.h>

#include <fstream>

#include "reconfig/scene/scene_file.h"
#include "studio_test_util.h"

namespace reconfig::studio {
namespace {

using Kind = AuthoringDialog::Kind;

class AuthoringDialogs : public ::testing::Test {
 protected:
  void SetUp() override {
    frontend_ = std::make_unique<HeadlessFrontend>(1000, 700);
    ASSERT_TRUE(studio().open(bench_table_copy()));
    frontend_->run_frame();
  }
  Studio& studio() { return frontend_->studio(); }
  std::string design() { return scene::scene_to_json(studio().document()->scene(), "/"); }

  /// Opens `dialog`, draws a few frames with it, then presses its OK with its input: refused,
  /// the status bar saying `words`, the design as it was.
  void expect_refused(AuthoringDialog dialog, const std::string& words) {
    const std::string before = design();
    studio().open_authoring_dialog(dialog);
    frontend_->run_frame();
    ASSERT_TRUE(studio().authoring_dialog().has_value()) << "the dialog closed by itself";
    EXPECT_FALSE(studio().accept_authoring_dialog(dialog));
    EXPECT_NE(studio().status().find(words), std::string::npos) << studio().status();
    EXPECT_EQ(design(), before);
    EXPECT_FALSE(studio().document()->modified());
    EXPECT_FALSE(studio().accept_authoring_dialog({.kind = Kind::kRenamePart, .target = -1}));  // nothing to rename
  }

  std::unique_ptr<HeadlessFrontend> frontend_;
};

TEST_F(AuthoringDialogs, BadInputIsAMessageAndTheDesignIsUntouched) {
  const auto dir = studio().document()->file().parent_path();
  std::ofstream(dir / "empty.obj") << "# nothing\n";
  const int seat = studio().document()->scene().find_part("seat");
  expect_refused({.kind = Kind::kImportMeshes, .text = "/no/such/mesh.stl"}, "cannot import /no/such/mesh.stl");
  expect_refused({.kind = Kind::kImportMeshes, .text = (dir / "empty.obj").string()}, "no triangles");
  expect_refused({.kind = Kind::kImportMeshes, .text = " ; "}, "no mesh file");
  expect_refused({.kind = Kind::kReplaceMesh, .target = seat, .text = (dir / "empty.obj").string()}, "no triangles");
  expect_refused({.kind = Kind::kAddPrimitive, .text = "seat"}, "already a part named \"seat\"");
  expect_refused({.kind = Kind::kAddPrimitive, .text = "thin", .sizes = {0.1, -1, 0.1}}, "sizes must be positive");
  expect_refused({.kind = Kind::kRenamePart, .target = seat, .text = "backrest"}, "already a part named");
  expect_refused({.kind = Kind::kRenamePart, .target = seat, .text = ""}, "needs a name");
  expect_refused({.kind = Kind::kDuplicate, .target = seat, .text = "seat"}, "already a part named");
  expect_refused({.kind = Kind::kAddState, .text = "table"}, "already a state named");
  expect_refused({.kind = Kind::kRenameState, .target = 0, .text = "table"}, "already a state named");
  expect_refused({.kind = Kind::kAddTransition, .text = "unfold", .from = 0, .to = 1}, "already a transition named");
  expect_refused({.kind = Kind::kAddTransition, .from = 0, .to = 7}, "from a state to a state");
  expect_refused({.kind = Kind::kRenameTransition, .target = 0, .text = "unfold_lifted"}, "already a transition");
  expect_refused({.kind = Kind::kDuplicate, .target = 0, .transition = true, .text = "unfold"}, "already a transition");
  expect_refused({.kind = Kind::kNewDesign, .text = studio().document()->file().string()}, "exists already");
}

TEST_F(AuthoringDialogs, EveryDialogDraws) {
  for (int kind = 0; kind <= static_cast<int>(Kind::kDuplicate); ++kind) {
    studio().open_authoring_dialog({.kind = static_cast<Kind>(kind), .target = 0, .message = "delete?"});
    for (int i = 0; i < 3; ++i) frontend_->run_frame();
    EXPECT_TRUE(studio().authoring_dialog().has_value()) << kind;
  }
}

TEST_F(AuthoringDialogs, TheAddPrimitiveDialogAddsAndSelects) {
  ASSERT_TRUE(studio().accept_authoring_dialog({.kind = Kind::kAddPrimitive, .text = "ball", .shape = 2, .sizes = {0.05, 0, 0}}));
  const int ball = studio().document()->scene().find_part("ball");
  ASSERT_GE(ball, 0);
  EXPECT_EQ(studio().selected_part(), ball);
  EXPECT_TRUE(std::holds_alternative<scene::SpherePrimitive>(studio().document()->scene().parts[ball].source));
}

}  // namespace
}  // namespace reconfig::studio
