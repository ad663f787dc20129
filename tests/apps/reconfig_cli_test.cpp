// The `reconfig` tool's contracts (FORMATS.md): exit codes, --json shapes, one-line errors.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "reconfig/geometry/load_mesh.h"
#include "reconfig/scene/scene_file.h"
#include "support/run_command.h"
#include "support/test_data.h"

namespace reconfig {
namespace {

using testing::run_reconfig;
namespace fs = std::filesystem;

std::string bench_table() { return (testing::source_dir() / "examples" / "bench-table" / "scene.json").string(); }

int count_lines(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

TEST(ReconfigCli, CheckFindsTheArmrestCollisionAndExitsOne) {
  const auto run = run_reconfig("check " + bench_table() + " --json");
  ASSERT_EQ(run.exit_code, 1) << run.err;
  const nlohmann::json result = nlohmann::json::parse(run.out);
  ASSERT_EQ(result["transitions"].size(), 2u);
  const auto& unfold = result["transitions"][0];
  EXPECT_EQ(unfold["name"], "unfold");
  ASSERT_EQ(unfold["intervals"].size(), 2u);
  for (const auto& ci : unfold["intervals"]) {
    // Fine at both ends, colliding midway (the paper's Figure 3).
    EXPECT_GT(ci["t0"].get<double>(), 0.0);
    EXPECT_LT(ci["t1"].get<double>(), 1.0);
    EXPECT_LT(ci["t0"].get<double>(), ci["t1"].get<double>());
    EXPECT_EQ(ci["parts"].size(), 2u);
    EXPECT_EQ(ci["parts"][0], "backrest");
    for (int k = 0; k < 3; ++k) EXPECT_LE(ci["box_min"][k].get<double>(), ci["box_max"][k].get<double>());
  }
  EXPECT_TRUE(result["transitions"][1]["intervals"].empty());
}

/// `--box-resolution 0` gives unrounded boxes; the default rounded ones hold them, with the
/// same times.
TEST(ReconfigCli, CheckBoxResolutionRoundsBoxesOutward) {
  const auto exact = run_reconfig("check " + bench_table() + " --json --transition unfold --box-resolution 0");
  const auto rounded = run_reconfig("check " + bench_table() + " --json --transition unfold");
  ASSERT_EQ(exact.exit_code, 1) << exact.err;
  ASSERT_EQ(rounded.exit_code, 1) << rounded.err;
  const nlohmann::json e = nlohmann::json::parse(exact.out)["transitions"][0]["intervals"];
  const nlohmann::json r = nlohmann::json::parse(rounded.out)["transitions"][0]["intervals"];
  ASSERT_EQ(e.size(), r.size());
  bool wider = false;
  for (std::size_t i = 0; i < e.size(); ++i) {
    EXPECT_EQ(e[i]["t0"], r[i]["t0"]);
    EXPECT_EQ(e[i]["t1"], r[i]["t1"]);
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(r[i]["box_min"][k].get<double>(), e[i]["box_min"][k].get<double>());
      EXPECT_GE(r[i]["box_max"][k].get<double>(), e[i]["box_max"][k].get<double>());
      wider = wider || r[i]["box_max"][k].get<double>() > e[i]["box_max"][k].get<double>();
    }
  }
  EXPECT_TRUE(wider);
  EXPECT_EQ(run_reconfig("check " + bench_table() + " --box-resolution -1").exit_code, 2);
}

/// The scene's collision settings are the engine's, and each option given overrides its own.
TEST(ReconfigCli, CheckUsesTheScenesCollisionSettingsUnlessOverridden) {
  const fs::path dir = testing::fresh_temp_dir();
  fs::copy(fs::path(bench_table()).parent_path() / "meshes", dir / "meshes", fs::copy_options::recursive);
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(bench_table()));
  scene["collision"] = {{"tolerance", 0.004}, {"dop", 8}, {"box_resolution", 0}, {"conservative", true}};
  std::ofstream(dir / "scene.json") << scene.dump(1);
  const std::string check = "check " + (dir / "scene.json").string() + " --json --transition unfold";

  const auto saved = run_reconfig(check);
  ASSERT_EQ(saved.exit_code, 1) << saved.err;
  const nlohmann::json used = nlohmann::json::parse(saved.out);
  EXPECT_EQ(used["tolerance"], 0.004);
  EXPECT_EQ(used["dop"], 8);
  EXPECT_EQ(used["box_resolution"], 0);
  EXPECT_EQ(used["conservative"], true);

  const auto overridden = run_reconfig(check + " --dop 80 --no-conservative --tolerance 0.002");
  ASSERT_EQ(overridden.exit_code, 1) << overridden.err;
  const nlohmann::json over = nlohmann::json::parse(overridden.out);
  EXPECT_EQ(over["tolerance"], 0.002);
  EXPECT_EQ(over["dop"], 80);
  EXPECT_EQ(over["box_resolution"], 0);  // not given: the scene's
  EXPECT_EQ(over["conservative"], false);

  // Without settings of its own, a scene gets the defaults.
  const nlohmann::json plain = nlohmann::json::parse(run_reconfig("check " + bench_table() + " --json").out);
  EXPECT_EQ(plain["tolerance"], 0.001);
  EXPECT_EQ(plain["dop"], 28);
  EXPECT_EQ(plain["conservative"], false);
}

TEST(ReconfigCli, CheckOfACollisionFreeTransitionExitsZero) {
  const auto run = run_reconfig("check " + bench_table() + " --transition unfold_lifted --samples 200");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("collision-free"), std::string::npos) << run.out;
}

TEST(ReconfigCli, CheckWritesReportFiles) {
  const fs::path dir = testing::fresh_temp_dir();
  const auto run = run_reconfig("check " + bench_table() + " --samples 100 --report " + (dir / "r.md").string() +
                                " --json-out " + (dir / "r.json").string());
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_TRUE(fs::exists(dir / "r.md"));
  EXPECT_EQ(nlohmann::json::parse(std::ifstream(dir / "r.json"))["transitions"].size(), 2u);
}

TEST(ReconfigCli, InfoListsPartsStatesAndTransitions) {
  const auto run = run_reconfig("info " + bench_table() + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json info = nlohmann::json::parse(run.out);
  EXPECT_EQ(info["parts"].size(), 6u);
  for (const auto& part : info["parts"]) EXPECT_TRUE(part["valid_solid"].get<bool>()) << part.dump();
  EXPECT_EQ(info["states"].size(), 2u);
}

TEST(ReconfigCli, PoseWritesOneNamedObjectPerPart) {
  const fs::path out = testing::fresh_temp_dir() / "posed.obj";
  const auto run = run_reconfig("pose " + bench_table() + " --transition unfold --time 0.5 -o " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::ifstream in(out);
  int faces = 0;
  std::vector<std::string> objects;
  for (std::string line; std::getline(in, line);) {
    faces += line.rfind("f ", 0) == 0;
    if (line.rfind("o ", 0) == 0) objects.push_back(line.substr(2));
  }
  const scene::Reconfigurable scene = scene::load_scene(bench_table());
  ASSERT_EQ(objects.size(), scene.parts.size());
  for (std::size_t p = 0; p < objects.size(); ++p) EXPECT_EQ(objects[p], scene.parts[p].name);
  EXPECT_EQ(faces, 40 + 40 + 36 + 36 + 12 + 12);
  EXPECT_EQ(geometry::load_mesh(out).face_count(), faces);  // and it reads back
  EXPECT_EQ(run_reconfig("pose " + bench_table() + " --state table -o " + out.string()).exit_code, 0);
}

struct BadCall {
  std::string name;
  std::string arguments;
  std::string scene_text;  ///< written to bad.json first if not empty
  std::string expected;    ///< substring of the one-line error
};

class ReconfigCliErrors : public ::testing::TestWithParam<BadCall> {};

TEST_P(ReconfigCliErrors, ExitTwoWithOneLineNamingThePlace) {
  const fs::path dir = testing::fresh_temp_dir();
  std::string arguments = GetParam().arguments;
  if (!GetParam().scene_text.empty()) {
    std::ofstream(dir / "bad.json") << GetParam().scene_text;
    arguments += " " + (dir / "bad.json").string();
  }
  const auto run = run_reconfig(arguments);
  EXPECT_EQ(run.exit_code, 2) << run.out << run.err;
  EXPECT_NE(run.err.find(GetParam().expected), std::string::npos) << run.err;
  if (!GetParam().scene_text.empty()) {
    EXPECT_EQ(count_lines(run.err), 1) << run.err;
  }
}

const char* kHeader = R"("format": "reconfig-scene", "version": 1, )";

INSTANTIATE_TEST_SUITE_P(
    Cli, ReconfigCliErrors,
    ::testing::Values(
        BadCall{"MissingFile", "check /nonexistent.json", "", "/nonexistent.json: file not found"},
        BadCall{"MalformedJson", "check", "{\"format\": ", "malformed JSON"},
        BadCall{"UnknownPart", "check",
                std::string("{") + kHeader + R"("parts": [{"name": "a", "sphere": {"radius": 1}}],
                  "states": [{"name": "s", "poses": {"b": {}}}]})",
                "states[0].poses.b: unknown part \"b\""},
        BadCall{"NonUnitQuaternion", "check",
                std::string("{") + kHeader + R"("parts": [{"name": "a", "sphere": {"radius": 1}}],
                  "states": [{"name": "s", "poses": {"a": {"rotation": [1, 2, 0, 0]}}}]})",
                "states[0].poses.a.rotation: quaternion"},
        BadCall{"UnknownTransition", "check --transition nope " + bench_table(), "", "no transition named \"nope\""},
        BadCall{"BadSamples", "check --samples 1 " + bench_table(), "", "samples"},
        BadCall{"UnknownSubcommand", "frobnicate", "", "subcommand"},
        BadCall{"PoseNeedsWhen", "pose " + bench_table() + " -o /tmp/x.obj", "", "--transition"}),
    [](const ::testing::TestParamInfo<BadCall>& param) { return param.param.name; });

}  // namespace
}  // namespace reconfig
