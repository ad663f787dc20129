// `reconfig sweep` and `reconfig carve` (docs/file-formats.md): outputs, JSON, exit codes.

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/run_command.h"
#include "support/test_data.h"

namespace reconfig {
namespace {

using testing::run_reconfig;
namespace fs = std::filesystem;

std::string bench_table() { return (testing::source_dir() / "examples" / "bench-table" / "scene.json").string(); }

TEST(SweepCli, WritesTheSweptVolumeAsAMesh) {
  const fs::path out = testing::fresh_temp_dir() / "swept.stl";
  const auto run = run_reconfig("sweep " + bench_table() +
                                " --transition unfold --part armrest_left --relative-to backrest --grid 0.01 "
                                "--offset 0.005 --json -o " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json result = nlohmann::json::parse(run.out);
  EXPECT_EQ(result["relative_to"], "backrest");
  EXPECT_DOUBLE_EQ(result["grid_step"].get<double>(), 0.01);
  EXPECT_GT(result["time_samples"].get<int>(), 10);
  EXPECT_GT(result["volume"].get<double>(), 0.05 * 0.38 * 0.04);  // more than the armrest itself
  EXPECT_GT(fs::file_size(out), 84u);
}

TEST(SweepCli, ScrewMethodWritesTheEnvelopeAndBothEndPoses) {
  const fs::path out = testing::fresh_temp_dir() / "envelope.obj";
  const auto run = run_reconfig("sweep " + bench_table() +
                                " --transition unfold --part armrest_left --relative-to backrest --grid 0.01 "
                                "--method screw --json -o " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json result = nlohmann::json::parse(run.out);
  EXPECT_EQ(result["method"], "screw");
  EXPECT_DOUBLE_EQ(result["tolerance"].get<double>(), 0.01);
  EXPECT_LE(result["motion_error"].get<double>(), 0.01);
  const int screws = result["screws"].get<int>(), segments = result["silhouette_segments"].get<int>();
  EXPECT_GT(screws, 10);
  EXPECT_GE(segments, 4 * screws);  // a moving box shows at least a loop of four edges
  // No piece turns by 5° (a point 0.19 from the armrest's center would move more than 0.01), so one
  // step each: two triangles per segment, then the armrest (a 12-triangle box) at both ends.
  EXPECT_EQ(result["steps"].get<int>(), screws);
  EXPECT_EQ(result["triangles"].get<int>(), 2 * segments + 24);
  EXPECT_GT(fs::file_size(out), 1000u);
}

TEST(SweepCli, BadInputIsExitTwo) {
  const fs::path out = testing::fresh_temp_dir() / "swept.obj";
  EXPECT_EQ(run_reconfig("sweep " + bench_table() + " --transition unfold --part nope -o " + out.string()).exit_code, 2);
  EXPECT_EQ(run_reconfig("sweep " + bench_table() + " --transition nope --part seat -o " + out.string()).exit_code, 2);
  EXPECT_EQ(run_reconfig("sweep " + bench_table() + " --transition unfold --part seat -o swept.ply").exit_code, 2);
  EXPECT_EQ(run_reconfig("sweep " + bench_table() + " --transition unfold --part seat --method stamp -o " + out.string())
                .exit_code,
            2);
  EXPECT_EQ(run_reconfig("carve " + bench_table() + " --transition unfold --part seat --by seat -o " +
                         (out.parent_path() / "x.json").string())
                .exit_code,
            2);
  EXPECT_FALSE(fs::exists(out));
}

TEST(CarveCli, CarvedBackrestNoLongerHitsTheArmrests) {
  const fs::path dir = testing::fresh_temp_dir();
  const std::string before = "check " + bench_table() + " --transition unfold";
  ASSERT_EQ(run_reconfig(before).exit_code, 1);  // the armrests hit the backrest first
  const fs::path out = dir / "carved.json";
  const auto run = run_reconfig("carve " + bench_table() +
                                " --transition unfold --part backrest --by armrest_left,armrest_right --offset 0.005 "
                                "--json -o " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const nlohmann::json result = nlohmann::json::parse(run.out);
  EXPECT_TRUE(result["collision_free"].get<bool>());
  EXPECT_LT(result["volume_after"].get<double>(), result["volume_before"].get<double>());
  EXPECT_EQ(result["sweeps"].size(), 2u);
  EXPECT_TRUE(fs::exists(dir / "meshes" / "backrest-carved.obj"));
  const std::string scene = out.string() + " --allow-outside-paths --transition unfold";
  EXPECT_EQ(run_reconfig("check " + scene).exit_code, 0);
  EXPECT_EQ(run_reconfig("check " + scene + " --reference --samples 400").exit_code, 0);
}

}  // namespace
}  // namespace reconfig
