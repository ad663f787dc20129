// What counts as unsaved: undoing back to the saved version is clean again (and leaves no
// autosave to recover); closing with Discard throws the edits and their autosave away, so the
// next open does not offer to recover them.

#include <gtest/gtest.h>

#include "document.h"
#include "reconfig/scene/edits.h"
#include "studio_test_util.h"

namespace reconfig::studio {
namespace {

using std::chrono::milliseconds;

/// An edit that is always valid: a collision tolerance of its own.
std::unique_ptr<scene::Command> tolerance(double value) {
  return scene::set_collision_settings(scene::CollisionSettings{.tolerance = value});
}

TEST(UnsavedChanges, UndoingBackToTheSavedVersionIsClean) {
  const std::filesystem::path file = bench_table_copy();
  const auto document = Document::open(file);
  EXPECT_FALSE(document->modified());
  ASSERT_EQ(document->execute(tolerance(0.002)), "");
  EXPECT_TRUE(document->modified());
  EXPECT_EQ(document->autosave_if_due(Document::Clock::now(), milliseconds(0)), "");
  ASSERT_TRUE(Document::has_recovery(file));

  ASSERT_TRUE(document->undo());
  EXPECT_FALSE(document->modified());
  EXPECT_FALSE(Document::has_recovery(file)) << "the autosave of an undone edit is nothing to recover";
  EXPECT_EQ(document->autosave_if_due(Document::Clock::now() + milliseconds(10), milliseconds(0)), "");
  EXPECT_FALSE(Document::has_recovery(file)) << "nor is there anything to autosave";
  ASSERT_TRUE(document->redo());
  EXPECT_TRUE(document->modified());

  // Saved after the edit: undoing it is a change, redoing it is clean again.
  document->save();
  EXPECT_FALSE(document->modified());
  ASSERT_TRUE(document->undo());
  EXPECT_TRUE(document->modified());
  ASSERT_TRUE(document->redo());
  EXPECT_FALSE(document->modified());

  // Undone and replaced by another edit, the saved version is out of reach of undo and redo.
  ASSERT_TRUE(document->undo());
  ASSERT_EQ(document->execute(tolerance(0.003)), "");
  EXPECT_TRUE(document->modified());
  ASSERT_TRUE(document->undo());
  EXPECT_TRUE(document->modified());
}

TEST(UnsavedChanges, ARecoveredAutosaveIsModifiedUntilSaved) {
  const std::filesystem::path file = bench_table_copy();
  const auto document = Document::open(file);
  ASSERT_EQ(document->execute(tolerance(0.002)), "");
  EXPECT_EQ(document->autosave_if_due(Document::Clock::now(), milliseconds(0)), "");
  const auto recovered = Document::recover(file);
  EXPECT_TRUE(recovered->modified());
  ASSERT_EQ(recovered->execute(tolerance(0.003)), "");
  ASSERT_TRUE(recovered->undo());
  EXPECT_TRUE(recovered->modified());
}

TEST(UnsavedChanges, DiscardOnQuitRemovesTheAutosave) {
  const std::filesystem::path file = bench_table_copy();
  StudioOptions options;
  options.autosave_interval = milliseconds(0);
  HeadlessFrontend frontend(800, 600, options);
  Studio& studio = frontend.studio();
  ASSERT_TRUE(studio.open(file)) << studio.status();
  frontend.run_frame();
  studio.select_part(studio.document()->scene().find_part("seat"));
  studio.set_time(0.5);
  motion::Pose pose = *studio.selected_pose();
  pose.translation.x() += 0.1;
  ASSERT_TRUE(studio.apply_pose(pose));
  frontend.run_frame();
  ASSERT_TRUE(Document::has_recovery(file));

  studio.request_close();
  EXPECT_FALSE(studio.quit_requested()) << "unsaved edits: it asks first";
  studio.discard_and_quit();
  EXPECT_TRUE(studio.quit_requested());
  EXPECT_FALSE(std::filesystem::exists(Document::autosave_path(std::filesystem::absolute(file))));
  EXPECT_FALSE(Document::has_recovery(file));
}

}  // namespace
}  // namespace reconfig::studio
