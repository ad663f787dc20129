// Sculpting in the studio, driven headless: the bench-table's armrests pushed back by one
// stroke each stop colliding with the backrest, and undo brings the collisions back.

#include <gtest/gtest.h>

#include <filesystem>
#include <variant>

#include "script.h"
#include "bench_table_unfold.h"

namespace reconfig::studio {
namespace {

using std::chrono::milliseconds;

using StudioSculpt = BenchTableUnfold;

TEST_F(StudioSculpt, PushingTheArmrestsBackFreesUnfoldAndUndoBringsTheCollisionsBack) {
  ASSERT_EQ(intervals_shown(), 2u);  // the backrest hits both armrests
  const int vertices = studio().document()->scene().parts[studio().document()->scene().find_part("armrest_left")].mesh.vertex_count();
  for (const char* armrest : {"armrest_left", "armrest_right"}) {
    studio().select_part(studio().document()->scene().find_part(armrest));
    Studio::SculptSettings& settings = studio().sculpt_settings();
    settings.shape = 1;
    settings.size = Eigen::Vector3d::Constant(0.2);
    settings.center = {0, -0.25, 0};
    settings.coating = 0.08;
    settings.stroke = 0;
    settings.translation = {0, 0.14, 0};
    ASSERT_TRUE(studio().sculpt_selected_part()) << studio().status();
    EXPECT_NE(studio().status().find("sculpted " + std::string(armrest)), std::string::npos) << studio().status();
  }
  ASSERT_TRUE(frontend_->run_until_collisions_current(milliseconds(60000)));
  EXPECT_EQ(intervals_shown(), 0u);
  EXPECT_EQ(studio().document()->scene().parts[studio().document()->scene().find_part("armrest_left")].mesh.vertex_count(), vertices);
  ASSERT_TRUE(studio().undo());
  ASSERT_TRUE(frontend_->run_until_collisions_current(milliseconds(60000)));
  EXPECT_EQ(intervals_shown(), 1u);  // the left armrest is sculpted, the right one is back
  // Saving writes the sculpted mesh beside the design.
  studio().document()->save();
  EXPECT_TRUE(std::filesystem::exists(studio().document()->file().parent_path() / "meshes" / "armrest_left.obj"));
}

TEST_F(StudioSculpt, TheAutosaveKeepsSculptedMeshesAndRecoversThem) {
  const int armrest = studio().document()->scene().find_part("armrest_left");
  studio().select_part(armrest);
  Studio::SculptSettings& settings = studio().sculpt_settings();
  settings.shape = 1;
  settings.size = Eigen::Vector3d::Constant(0.2);
  settings.center = {0, -0.25, 0};
  settings.coating = 0.08;
  settings.translation = {0, 0.14, 0};
  ASSERT_TRUE(studio().sculpt_selected_part()) << studio().status();
  const geometry::Mesh sculpted = studio().document()->scene().parts[armrest].mesh;
  const std::filesystem::path file = studio().document()->file();
  ASSERT_EQ(studio().document()->autosave_if_due(Document::Clock::now(), milliseconds(0)), "");
  ASSERT_TRUE(Document::has_recovery(file));
  // After a crash: the recovered design has the sculpted mesh, still as an edit (the next save
  // writes it beside the design, not into the autosave's folder).
  const auto recovered = Document::recover(file, {});
  const scene::Part& part = recovered->scene().parts[armrest];
  EXPECT_TRUE(std::holds_alternative<scene::EditedMesh>(part.source));
  EXPECT_EQ(part.mesh.V, sculpted.V);
  EXPECT_EQ(part.mesh.F, sculpted.F);
  // Discarding removes the autosave and its meshes.
  studio().document()->discard_autosave();
  EXPECT_FALSE(Document::has_recovery(file));
  EXPECT_FALSE(std::filesystem::exists(Document::autosave_meshes_path(file)));
}

TEST_F(StudioSculpt, BadSettingsAndNoSelectionAreRefusedWithAReason) {
  EXPECT_FALSE(studio().sculpt_selected_part());
  EXPECT_NE(studio().status().find("select a part"), std::string::npos) << studio().status();
  studio().select_part(studio().document()->scene().find_part("seat"));
  studio().sculpt_settings().coating = 0;
  EXPECT_FALSE(studio().sculpt_selected_part());
  EXPECT_NE(studio().status().find("coating"), std::string::npos) << studio().status();
  EXPECT_TRUE(studio().document()->undo_label().empty());  // nothing was edited
}

TEST_F(StudioSculpt, ScriptsSculpt) {
  run_script(*frontend_,
             "expect-collisions 2\n"
             "sculpt armrest_left box 0.2 0.2 0.2 0.08 0 -0.25 0 translate 0 0.14 0\n"
             "sculpt armrest_right box 0.2 0.2 0.2 0.08 0 -0.25 0 translate 0 0.14 0\n"
             "wait-collisions\n"
             "expect-collisions 0\n",
             "sculpt script");
  EXPECT_THROW(run_script(*frontend_, "sculpt seat cone 1 1 1 0.1 0 0 0 translate 0 0 1\n", "bad tool"), ScriptError);
  EXPECT_THROW(run_script(*frontend_, "sculpt seat sphere 0.1 0 0 0.1 0 0 0 scale 2 mirror w\n", "bad mirror"), ScriptError);
}

}  // namespace
}  // namespace reconfig::studio
