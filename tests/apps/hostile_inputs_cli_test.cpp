// The tool on hostile inputs (issue 25): exit code 2 and one bounded, escaped line naming the
// file and the JSON path; `--allow-outside-paths` lets a scene read meshes outside its folder.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/run_command.h"
#include "support/test_data.h"

namespace reconfig {
namespace {

using testing::run_reconfig;
namespace fs = std::filesystem;

/// `design/scene.json` whose only part is the mesh at `mesh`, next to `secret.obj` outside it.
fs::path design_reading(const std::string& mesh) {
  const fs::path dir = testing::fresh_temp_dir();
  fs::create_directories(dir / "design");
  std::ofstream(dir / "secret.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  const nlohmann::json scene = {{"format", "reconfig-scene"}, {"version", 1}, {"units", "m"},
                                {"parts", {{{"name", "leak"}, {"mesh", mesh}}}}, {"states", nlohmann::json::array()}};
  std::ofstream(dir / "design" / "scene.json") << scene.dump();
  return dir / "design" / "scene.json";
}

TEST(HostileInputsCli, MeshesOutsideTheDesignNeedAllowOutsidePaths) {
  const fs::path scene = design_reading("../secret.obj");
  const std::string png = (scene.parent_path() / "out.png").string();
  for (const std::string& command : {std::string("info"), std::string("check"), "render -o " + png}) {
    const auto refused = run_reconfig(command + " " + scene.string());
    EXPECT_EQ(refused.exit_code, 2) << command << ": " << refused.err;
    EXPECT_NE(refused.err.find("parts[0].mesh: \"../secret.obj\" leads out of the file's folder"), std::string::npos)
        << command << ": " << refused.err;
  }
  const auto allowed = run_reconfig("info --allow-outside-paths " + scene.string());
  EXPECT_EQ(allowed.exit_code, 0) << allowed.err;
  const std::string posed = (scene.parent_path() / "posed.obj").string();
  EXPECT_NE(run_reconfig("pose " + scene.string() + " --state x -o " + posed).err.find("leads out"), std::string::npos);
  EXPECT_NE(run_reconfig("pose --allow-outside-paths " + scene.string() + " --state x -o " + posed).err.find("no state"),
            std::string::npos);
}

TEST(HostileInputsCli, AFifoSceneIsRefusedAtOnce) {
  const fs::path fifo = testing::fresh_temp_dir() / "scene.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto run = run_reconfig("info " + fifo.string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(fifo.string() + ": is not a regular file (a FIFO)"), std::string::npos) << run.err;
}

TEST(HostileInputsCli, EscapeSequencesInAnErrorAreNotPrintedRaw) {
  const fs::path scene = design_reading("mesh\x1b[2J.obj");
  const auto run = run_reconfig("info '" + scene.string() + "'");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err.find('\x1b'), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("mesh\\x1b[2J.obj"), std::string::npos) << run.err;
}

TEST(HostileInputsCli, AToleranceTooFineForTheDesignIsRefusedAtOnce) {
  const fs::path scene = testing::fresh_temp_dir() / "beam.json";
  // A beam 1e10 long making a quarter turn: at the default 1 mm, minutes of time steps.
  std::ofstream(scene) << R"({"format": "reconfig-scene", "version": 1, "units": "m",
    "parts": [{"name": "beam", "box": {"size": [1e10, 0.05, 0.5]}}],
    "states": [{"name": "a"}, {"name": "b", "poses": {"beam": {"rotation": [0.70710678118654757, 0, 0, 0.70710678118654757]}}}],
    "transitions": [{"name": "turn", "from": "a", "to": "b", "tracks": {"beam": {"rotation": [
      {"time": 0, "quaternion": [1, 0, 0, 0]}, {"time": 1, "quaternion": [0.70710678118654757, 0, 0, 0.70710678118654757]}]}}}]})";
  const auto start = std::chrono::steady_clock::now();
  const auto run = run_reconfig("check " + scene.string());
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find(scene.string() + ": collision.tolerance: a tolerance of 0.001 is too fine"), std::string::npos)
      << run.err;
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));  // minutes before
  EXPECT_EQ(run_reconfig("check --tolerance 100 " + scene.string()).exit_code, 0);
}

TEST(HostileInputsCli, CtrlCStopsALongCheckCleanly) {
  // A beam 1e5 long turning there and back at 1 mm: 1.6 s of time steps, within the tolerance rule.
  const fs::path scene = testing::fresh_temp_dir() / "long.json";
  std::ofstream(scene) << R"({"format": "reconfig-scene", "version": 1, "units": "m",
    "parts": [{"name": "beam", "box": {"size": [1e5, 0.05, 0.5]}}, {"name": "post", "box": {"size": [0.1, 0.1, 1]}}],
    "states": [{"name": "a", "poses": {"post": {"translation": [0, 1, 0]}}},
               {"name": "b", "poses": {"post": {"translation": [0, 1, 0]},
                                       "beam": {"rotation": [0.70710678118654757, 0, 0, 0.70710678118654757]}}}],
    "transitions": [{"name": "turn", "from": "a", "to": "b", "tracks": {"beam": {"rotation": [
      {"time": 0, "quaternion": [1, 0, 0, 0]}, {"time": 1, "quaternion": [0.70710678118654757, 0, 0, 0.70710678118654757]}]}}},
                    {"name": "back", "from": "b", "to": "a", "tracks": {"beam": {"rotation": [
      {"time": 0, "quaternion": [0.70710678118654757, 0, 0, 0.70710678118654757]}, {"time": 1, "quaternion": [1, 0, 0, 0]}]}}}]})";
  const auto start = std::chrono::steady_clock::now();
  const auto run = testing::run_reconfig_interrupted({"check", scene.string()});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_NE(run.exit_code, -1) << "killed by a signal, not stopped: " << run.err;
  EXPECT_EQ(run.exit_code, 130) << run.err;
  EXPECT_NE(run.err.find("check cancelled (Ctrl+C): no result"), std::string::npos) << run.err;
  EXPECT_LT(seconds, 5.0);  // no hang after Ctrl+C
}

}  // namespace
}  // namespace reconfig
