// The studio after a crash or a kill during a save (issue 25): stale temporaries are cleaned, an
// autosave is offered even when the scene file is corrupt or gone, and a long error is shown
// whole.

#include <gtest/gtest.h>

#include <fstream>

#include "document.h"
#include "frontend.h"
#include "studio.h"
#include "studio_test_util.h"

namespace reconfig::studio {
namespace {

namespace fs = std::filesystem;

class StudioRecovery : public ::testing::Test {
 protected:
  void SetUp() override {
    scene_file_ = bench_table_copy();
    frontend_ = std::make_unique<HeadlessFrontend>(1000, 700, StudioOptions{});
  }

  Studio& studio() { return frontend_->studio(); }

  /// An autosave of the example with one part renamed, as a crash would have left it.
  void leave_autosave() {
    std::ifstream in(scene_file_);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.replace(text.find("\"seat\""), 6, "\"saved\"");
    std::ofstream(Document::autosave_path(scene_file_)) << text;
  }

  fs::path scene_file_;
  std::unique_ptr<HeadlessFrontend> frontend_;
};

TEST_F(StudioRecovery, OpeningCleansTheTemporariesOfAKilledSave) {
  const fs::path stale = scene_file_.string() + ".tmp";
  const fs::path stale_autosave = Document::autosave_path(scene_file_).string() + ".tmp";
  std::ofstream(stale) << std::string(1'000'000, '{');
  std::ofstream(stale_autosave) << "{";
  ASSERT_TRUE(studio().open(scene_file_)) << studio().status();
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_FALSE(fs::exists(stale_autosave));
}

TEST_F(StudioRecovery, ACorruptFileWithAnAutosaveOffersTheAutosave) {
  leave_autosave();
  std::ofstream(scene_file_) << "{\"format\": \"reconfig-sce";  // newer than the autosave, and broken
  EXPECT_TRUE(studio().open(scene_file_));
  EXPECT_NE(studio().status().find("its autosave can be recovered"), std::string::npos) << studio().status();
  EXPECT_EQ(studio().recovery_candidate(), fs::absolute(scene_file_));
  frontend_->run_frame();  // the modal
  ASSERT_TRUE(studio().recover_autosave()) << studio().status();
  ASSERT_NE(studio().document(), nullptr);
  EXPECT_GE(studio().document()->scene().find_part("saved"), 0);
  EXPECT_TRUE(studio().document()->modified());
  EXPECT_TRUE(studio().recovery_candidate().empty());
  frontend_->run_frame();
}

TEST_F(StudioRecovery, AGoneFileWithAnAutosaveOffersTheAutosave) {
  leave_autosave();
  fs::remove(scene_file_);
  EXPECT_TRUE(studio().open(scene_file_));
  ASSERT_TRUE(studio().recover_autosave()) << studio().status();
  EXPECT_EQ(studio().document()->file(), fs::absolute(scene_file_));
}

TEST_F(StudioRecovery, ABadFileWithoutAutosaveIsStillAnError) {
  std::ofstream(scene_file_) << "{";
  EXPECT_FALSE(studio().open(scene_file_));
  EXPECT_TRUE(studio().recovery_candidate().empty());
}

TEST_F(StudioRecovery, ALongErrorIsShownWholeInAWindow) {
  ASSERT_TRUE(studio().open(scene_file_));
  frontend_->run_frame();
  EXPECT_FALSE(studio().status_window_open()) << "a short status fits the bar";
  const fs::path deep = scene_file_.parent_path() / (std::string(200, 'd') + ".json");
  std::ofstream(deep) << "{\"format\": \"reconfig-scene\", \"version\": 1, \"parts\": [{\"name\": 3}]}";
  EXPECT_FALSE(studio().open(deep));
  frontend_->run_frame();
  EXPECT_TRUE(studio().status_window_open()) << studio().status();
  frontend_->run_frame();
  EXPECT_TRUE(studio().status_window_open()) << "stays until closed";
}

TEST_F(StudioRecovery, MeshesOutsideTheDesignOpenOnlyWhenAllowed) {
  const fs::path moved = scene_file_.parent_path() / "elsewhere" / "scene.json";
  fs::create_directories(moved.parent_path());
  std::ifstream in(scene_file_);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (std::size_t at = text.find("\"meshes/"); at != std::string::npos; at = text.find("\"meshes/", at + 4))
    text.insert(at + 1, "../");
  std::ofstream(moved) << text;
  EXPECT_FALSE(studio().open(moved));
  EXPECT_NE(studio().status().find("--allow-outside-paths"), std::string::npos) << studio().status();
  StudioOptions allowing;
  allowing.load.allow_outside_paths = true;
  frontend_.reset();  // one studio at a time (one ImGui context)
  frontend_ = std::make_unique<HeadlessFrontend>(1000, 700, allowing);
  EXPECT_TRUE(studio().open(moved)) << studio().status();
}

}  // namespace
}  // namespace reconfig::studio
