// `reconfig render`: headless pictures (EGL surfaceless, Mesa llvmpipe), PNG output.

#include <gtest/gtest.h>

#define STB_IMAGE_IMPLEMENTATION  // the only user of stb_image in this test executable
#include <stb/stb_image.h>

#include <fstream>
#include <iterator>
#include <memory>
#include <set>

#include "support/run_command.h"
#include "support/test_data.h"

namespace reconfig {
namespace {

using testing::run_reconfig;

std::string bench_table() { return (testing::source_dir() / "examples" / "bench-table" / "scene.json").string(); }

struct Png {
  int width = 0, height = 0;
  std::set<std::uint32_t> colors;
};

Png read_png(const std::filesystem::path& path) {
  Png png;
  int channels = 0;
  std::unique_ptr<unsigned char, void (*)(void*)> pixels(stbi_load(path.c_str(), &png.width, &png.height, &channels, 4),
                                                         stbi_image_free);
  if (!pixels) return png;
  for (int i = 0; i < png.width * png.height; ++i) {
    const unsigned char* p = pixels.get() + 4 * i;
    png.colors.insert(p[0] | p[1] << 8 | p[2] << 16 | static_cast<std::uint32_t>(p[3]) << 24);
  }
  return png;
}

TEST(RenderCli, WritesAPictureOfTheRequestedSize) {
  const auto out = testing::fresh_temp_dir() / "unfold.png";
  const auto run = run_reconfig("render " + bench_table() + " --transition unfold --time 0.4 --intervals --ghosts 2 "
                                "--size 320x200 -o " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("2 collision interval boxes"), std::string::npos) << run.out;
  const Png png = read_png(out);
  EXPECT_EQ(png.width, 320);
  EXPECT_EQ(png.height, 200);
  EXPECT_GT(png.colors.size(), 50u) << "a picture, not a flat color";
}

TEST(RenderCli, StateCameraAndSelection) {
  const auto dir = testing::fresh_temp_dir();
  const auto run = run_reconfig("render " + bench_table() + " --state table --camera 30,40,4 --select backrest --no-grid "
                                "--size 96x64 -o " + (dir / "table.png").string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Png png = read_png(dir / "table.png");
  EXPECT_EQ(png.width, 96);
  EXPECT_GT(png.colors.size(), 10u);
}

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A wall and a drawer that slides out toward −x; with `view`, the scene's saved view.
std::filesystem::path drawer_scene(const std::filesystem::path& dir, const std::string& view = "") {
  const auto file = dir / "drawer.json";
  std::ofstream(file) << R"({"format": "reconfig-scene", "version": 1,
    "parts": [{"name": "wall", "box": {"size": [0.1, 2, 1]}},
              {"name": "drawer", "box": {"size": [1, 0.6, 0.3]}, "color": [0.4, 0.6, 0.5]}],
    "states": [{"name": "in", "poses": {"wall": {"translation": [0.6, 0, 0]}}},
               {"name": "out", "poses": {"wall": {"translation": [0.6, 0, 0]}, "drawer": {"translation": [-0.8, 0, 0]}}}])"
                      << view << "}";
  return file;
}

std::string render_drawer(const std::filesystem::path& scene, const std::string& camera) {
  const auto out = scene.parent_path() / "drawer.png";
  const auto run = run_reconfig("render " + scene.string() + camera + " --size 96x64 --msaa 0 -o " + out.string());
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return file_bytes(out);
}

// Without --camera the picture is taken from the side the drawer slides out to (−x, turned
// 30°, as the studio opens it), and a view saved in the scene wins over that.
TEST(RenderCli, DefaultCameraLooksAtTheWorkingSideUnlessTheSceneSavedOne) {
  const auto dir = testing::fresh_temp_dir();
  const auto scene = drawer_scene(dir);
  const std::string working_side = render_drawer(scene, "");
  EXPECT_EQ(working_side, render_drawer(scene, " --camera 150,25"));
  EXPECT_NE(working_side, render_drawer(scene, " --camera 60,25"));

  const auto saved = drawer_scene(
      dir, R"(, "view": {"target": [0, 0, 0.2], "distance": 3, "yaw_degrees": -90, "pitch_degrees": 10})");
  const std::string from_saved = render_drawer(saved, "");
  EXPECT_NE(from_saved, working_side);
  EXPECT_EQ(from_saved, render_drawer(saved, ""));
  EXPECT_EQ(render_drawer(saved, " --camera 150,25"), working_side) << "--camera wins over the saved view";
}

TEST(RenderCli, BadInputIsOneLineAndExitTwo) {
  const auto out = (testing::fresh_temp_dir() / "x.png").string();
  for (const std::string& args : {" --transition nope --time 0.5 -o " + out, " --state table --camera 10 -o " + out,
                                 " --state table --size 12x9000 -o " + out, " --state table -o " + out + ".jpg",
                                 " --state table --ghosts 2 -o " + out, " --state table --select nope -o " + out}) {
    const auto run = run_reconfig("render " + bench_table() + args);
    EXPECT_EQ(run.exit_code, 2) << args;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << args << ": " << run.err;
  }
}

}  // namespace
}  // namespace reconfig
