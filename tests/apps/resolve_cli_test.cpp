// `reconfig resolve` and `reconfig check --energy` (docs/file-formats.md): JSON shapes, exit codes.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/run_command.h"
#include "support/test_data.h"

namespace reconfig {
namespace {

using testing::run_reconfig;

std::string bench_table() { return (testing::source_dir() / "examples" / "bench-table" / "scene.json").string(); }

TEST(ResolveCli, CheckEnergyGivesEveryIntervalAnEnergyAndASeverityTime) {
  const auto run = run_reconfig("check " + bench_table() + " --json --energy --transition unfold");
  ASSERT_EQ(run.exit_code, 1) << run.err;
  const nlohmann::json result = nlohmann::json::parse(run.out);
  const auto& intervals = result["transitions"][0]["intervals"];
  ASSERT_EQ(intervals.size(), 2u);
  for (const auto& ci : intervals) {
    EXPECT_GT(ci["energy"].get<double>(), 0);
    EXPECT_NEAR(ci["energy"].get<double>(),
                ci["contour_energy"].get<double>() + ci["penetration_energy"].get<double>() +
                    ci["proximity_energy"].get<double>(),
                1e-9);
    EXPECT_GT(ci["proximity_energy"].get<double>(), 0);  // the parts cross: D = c throughout
    EXPECT_GE(ci["severity_time"].get<double>(), ci["t0"].get<double>() - 0.02);
    EXPECT_LE(ci["severity_time"].get<double>(), ci["t1"].get<double>() + 0.02);
  }
  const auto text = run_reconfig("check " + bench_table() + " --energy --transition unfold");
  EXPECT_NE(text.out.find("most severe at t ="), std::string::npos) << text.out;
}

TEST(ResolveCli, HintGivesADirectionPerDegreeOfFreedom) {
  const auto run = run_reconfig("resolve " + bench_table() + " --transition unfold --hint backrest --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json result = nlohmann::json::parse(run.out);
  EXPECT_EQ(result["transition"], "unfold");
  EXPECT_EQ(result["part"], "backrest");
  EXPECT_GT(result["energy"].get<double>(), 0);
  // unfold has two keys per track: the handles that shape how the backrest leaves and arrives.
  ASSERT_FALSE(result["hints"].empty());
  for (const auto& hint : result["hints"]) {
    const std::string kind = hint["kind"];
    EXPECT_TRUE(kind == "handle_in" || kind == "handle_out") << kind;
    ASSERT_EQ(hint["direction"].size(), 3u);
    double norm = 0;
    for (const auto& x : hint["direction"]) norm += x.get<double>() * x.get<double>();
    EXPECT_NEAR(norm, 1.0, 1e-9);
  }
}

TEST(ResolveCli, AutoWritesACollisionFreeDesign) {
  const auto out = testing::fresh_temp_dir() / "resolved.json";
  const auto run = run_reconfig("resolve " + bench_table() + " --transition unfold --auto -o " + out.string() + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const nlohmann::json result = nlohmann::json::parse(run.out);
  EXPECT_TRUE(result["collision_free"].get<bool>());
  EXPECT_FALSE(result["rounds"].empty());
  // The written design checks collision-free with the engine and the reference (its meshes
  // stay where they were, outside the temporary folder it was written to).
  const std::string check = "check " + out.string() + " --allow-outside-paths --transition unfold";
  EXPECT_EQ(run_reconfig(check).exit_code, 0);
  EXPECT_EQ(run_reconfig(check + " --reference").exit_code, 0);
  const auto text = run_reconfig("resolve " + bench_table() + " --transition unfold --auto -o " + out.string());
  EXPECT_NE(text.out.find("round 1: backrest × armrest_"), std::string::npos) << text.out;
}

TEST(ResolveCli, BadArgumentsExitTwoWithAMessage) {
  EXPECT_EQ(run_reconfig("resolve " + bench_table() + " --transition nope --hint backrest").exit_code, 2);
  const auto part = run_reconfig("resolve " + bench_table() + " --transition unfold --hint nothing");
  EXPECT_EQ(part.exit_code, 2);
  EXPECT_NE(part.err.find("no part named \"nothing\""), std::string::npos) << part.err;
  EXPECT_EQ(run_reconfig("resolve " + bench_table() + " --transition unfold").exit_code, 2);
  EXPECT_EQ(run_reconfig("resolve " + bench_table() + " --transition unfold --auto").exit_code, 2);
}

}  // namespace
}  // namespace reconfig
