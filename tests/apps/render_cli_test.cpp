// `reconfig render`: headless pictures (EGL surfaceless, Mesa llvmpipe), PNG output.

#include <gtest/gtest.h>

#define STB_IMAGE_IMPLEMENTATION  // the only user of stb_image in this test executable
#include <stb/stb_image.h>

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
