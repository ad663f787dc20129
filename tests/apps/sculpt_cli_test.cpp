// `reconfig sculpt` (docs/file-formats.md): JSON shape, strokes in order, refusals exit 2 and
// write nothing, and the bench-table's sculpted armrests (examples/bench-table/sculpt-armrests.sh).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/run_command.h"
#include "support/test_data.h"

namespace reconfig {
namespace {

using testing::run_reconfig;

std::string example(const std::string& file) {
  return (testing::source_dir() / "examples" / "bench-table" / file).string();
}

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Every vertex coordinate of an OBJ file, in order.
std::vector<double> obj_coordinates(const std::filesystem::path& path) {
  std::vector<double> coordinates;
  std::istringstream lines(read(path));
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind("v ", 0) != 0) continue;
    std::istringstream values(line.substr(2));
    double x = 0;
    while (values >> x) coordinates.push_back(x);
  }
  return coordinates;
}

/// The stroke of examples/bench-table/sculpt-armrests.sh.
const std::string kArmrestStroke = " --tool box:0.2,0.2,0.2 --at 0,-0.25,0 --coating 0.08 --translate 0,0.14,0";

TEST(SculptCli, TheArmrestScriptMakesUnfoldCollisionFree) {
  ASSERT_EQ(run_reconfig("check " + example("scene.json") + " --transition unfold").exit_code, 1);  // it collides
  const auto out = testing::fresh_temp_dir() / "armrest.obj";
  const auto run = run_reconfig("sculpt " + example("meshes/armrest.obj") + kArmrestStroke + " -o " + out.string() + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json report = nlohmann::json::parse(run.out);
  EXPECT_EQ(report["triangles_before"], report["triangles_after"]);
  ASSERT_EQ(report["strokes"].size(), 1u);
  const auto& stroke = report["strokes"][0];
  EXPECT_GT(stroke["substeps"].get<int>(), stroke["foldover_bound"].get<double>());
  EXPECT_GT(stroke["min_jacobian_determinant"].get<double>(), 0);
  EXPECT_GT(stroke["vertices_moved"].get<int>(), 1000);
  // The example's sculpted armrest is what the script makes, and the design with it is free.
  EXPECT_EQ(read(out), read(example("meshes/armrest-sculpted.obj")));
  const auto check = run_reconfig("check " + example("scene-sculpted.json"));
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
}

TEST(SculptCli, StrokesApplyInOrderAndAStrokeThenItsInverseGivesTheMeshBack) {
  const auto dir = testing::fresh_temp_dir();
  const std::string mesh = example("meshes/armrest.obj");
  const auto run = run_reconfig("sculpt " + mesh + " --tool sphere:0.03 --at 0,0.1,0.02 --coating 0.04 --translate 0,0,0.05"
                                " --scale 1.5 --scale 0.6666666666666666 --translate=0,0,-0.05 -o " + (dir / "back.obj").string() + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto strokes = nlohmann::json::parse(run.out)["strokes"];
  ASSERT_EQ(strokes.size(), 4u);
  EXPECT_EQ(strokes[0]["stroke"], "translate 0,0,0.05");
  EXPECT_EQ(strokes[1]["stroke"], "scale 1.5");
  EXPECT_EQ(strokes[3]["stroke"], "translate 0,0,-0.05");
  const std::vector<double> rest = obj_coordinates(mesh), back = obj_coordinates(dir / "back.obj");
  ASSERT_EQ(rest.size(), back.size());
  double largest = 0;
  for (std::size_t i = 0; i < rest.size(); ++i) largest = std::max(largest, std::abs(rest[i] - back[i]));
  EXPECT_LT(largest, 1e-6);
  EXPECT_GT(strokes[0]["vertices_moved"].get<int>(), 10);
}

TEST(SculptCli, RemeshingKeepsAPulledFeatureResolved) {
  const auto out = testing::fresh_temp_dir() / "pulled.obj";
  const auto run = run_reconfig("sculpt " + example("meshes/armrest.obj") + " --tool sphere:0.01 --at 0,0.19,0 --coating 0.02"
                                " --translate 0,0.1,0 --remesh 0.006 -o " + out.string() + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json report = nlohmann::json::parse(run.out);
  EXPECT_GT(report["triangles_after"].get<int>(), report["triangles_before"].get<int>());
  EXPECT_GT(report["strokes"][0]["splits"].get<int>(), 20);
}

TEST(SculptCli, AMirroredStrokeShapesBothSidesAlike) {
  // The armrest is symmetric in x = 0: a stroke on one side, mirrored, leaves it symmetric.
  const auto out = testing::fresh_temp_dir() / "mirrored.obj";
  const auto run = run_reconfig("sculpt " + example("meshes/armrest.obj") + " --tool sphere:0.01 --at 0.025,0.1,0.02"
                                " --coating 0.02 --translate 0.01,0,0.005 --mirror x -o " + out.string() + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::vector<double> v = obj_coordinates(out);
  std::vector<std::array<double, 3>> points, reflected;
  for (std::size_t i = 0; i + 2 < v.size(); i += 3) {
    points.push_back({v[i], v[i + 1], v[i + 2]});
    reflected.push_back({-v[i], v[i + 1], v[i + 2]});
  }
  std::sort(points.begin(), points.end());
  std::sort(reflected.begin(), reflected.end());
  double largest = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) largest = std::max(largest, std::abs(points[i][k] - reflected[i][k]));
  EXPECT_LT(largest, 1e-9);
  const std::vector<double> rest = obj_coordinates(example("meshes/armrest.obj"));
  double moved = 0;
  for (std::size_t i = 0; i < rest.size(); ++i) moved = std::max(moved, std::abs(rest[i] - v[i]));
  EXPECT_GT(moved, 0.005);  // the stroke did something
}

TEST(SculptCli, AMeshCanBeATool) {
  const auto dir = testing::fresh_temp_dir();
  // The armrest itself, 3 cm above, pressed 1.5 cm down into the armrest's top.
  const auto run = run_reconfig("sculpt " + example("meshes/armrest.obj") + " --tool mesh:" + example("meshes/armrest.obj") +
                                " --at 0,0,0.03 --coating 0.01 --translate 0,0,-0.015 -o " + (dir / "pressed.obj").string() + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_GT(nlohmann::json::parse(run.out)["strokes"][0]["vertices_moved"].get<int>(), 500);
  // An open mesh is not a tool.
  std::ofstream(dir / "open.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const auto open = run_reconfig("sculpt " + example("meshes/armrest.obj") + " --tool mesh:" + (dir / "open.obj").string() +
                                 " --coating 0.01 --translate 0,0,-0.015 -o " + (dir / "x.obj").string());
  EXPECT_EQ(open.exit_code, 2);
  EXPECT_NE(open.err.find("closed"), std::string::npos) << open.err;
}

TEST(SculptCli, ARefusedStrokeExitsTwoAndWritesNothing) {
  const auto out = testing::fresh_temp_dir() / "never.obj";
  const auto run = run_reconfig("sculpt " + example("meshes/armrest.obj") + kArmrestStroke + " --substeps 1 -o " + out.string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("refused"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(SculptCli, BadArgumentsExitTwoWithAMessage) {
  const std::string mesh = example("meshes/armrest.obj"), out = " -o " + (testing::fresh_temp_dir() / "x.obj").string();
  for (const char* arguments :
       {" --tool cone:1 --coating 0.1 --translate 0,0,1", " --tool sphere:-1 --coating 0.1 --translate 0,0,1",
        " --tool sphere:0.1 --coating 0 --translate 0,0,1", " --tool sphere:0.1 --coating 0.1 --translate 0,0",
        " --tool sphere:0.1 --coating 0.1 --rotate q,90", " --tool sphere:0.1 --coating 0.1",
        " --tool sphere:0.1 --coating 0.1 --scale 0", " --tool sphere:0.1 --coating 0.1 --translate 0,0,1 --mirror w",
        " --tool mesh:nowhere.obj --coating 0.1 --translate 0,0,1"}) {
    const auto run = run_reconfig("sculpt " + mesh + arguments + out);
    EXPECT_EQ(run.exit_code, 2) << arguments;
    EXPECT_NE(run.err.find("error"), std::string::npos) << arguments << ": " << run.err;
  }
}

}  // namespace
}  // namespace reconfig
