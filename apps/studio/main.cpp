// reconfig-studio [SCENE] — the interactive editor, or (with --screenshot, --frames, --script
// or --headless) the same UI run headless through EGL for scripts, tests and pictures.
//
// Exit codes: 0 success; 1 a script's expectation failed; 2 bad input (unreadable scene or
// script, bad option, no OpenGL context).

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <sstream>

#include "frame_times.h"
#include "frontend.h"
#include "reconfig/common/write_atomically.h"
#include "reconfig/render/image.h"
#include "script.h"

namespace {

using namespace reconfig;

struct Options {
  std::string scene, screenshot, script, frame_times, size = "1280x800";
  int frames = 0;
  bool headless = false, window = false, ghosts = false, no_wait = false;
  double time = -1;
  studio::StudioOptions studio;
  int dop = collision::halfspace_count(collision::DetectorOptions{}.dop);
};

/// Saves the frame as `file`, first (when `wait`) running frames until the collision picture
/// describes the design, as a script's `wait-collisions` does; says on stdout what it shows.
void save_screenshot(studio::HeadlessFrontend& frontend, const std::string& file, bool wait) {
  constexpr auto kTimeout = std::chrono::seconds(60);
  const bool detect = wait && frontend.studio().document();
  const bool detected = detect && frontend.run_until_collisions_current(kTimeout);
  if (detect && !detected)
    std::cerr << fmt::format("reconfig-studio: collision detection did not finish within {} s; the screenshot shows "
                             "it unfinished\n", kTimeout.count());
  render::write_png(file, frontend.screenshot());
  std::cout << fmt::format("wrote {}{}\n", file, detected ? " (collisions detected)" : "");
}

int run_headless(const Options& options, int width, int height) {
  studio::HeadlessFrontend frontend(width, height, options.studio);
  studio::Studio& studio = frontend.studio();
  studio.show_ghosts = options.ghosts;
  if (!options.scene.empty() && !studio.open(options.scene)) {
    std::cerr << "reconfig-studio: " << studio.status() << "\n";
    return 2;
  }
  if (options.time >= 0) studio.set_time(options.time);
  std::vector<double> times;
  frontend.run_frame();
  if (!options.script.empty()) {
    std::ifstream in(options.script);
    if (!in) {
      std::cerr << "reconfig-studio: cannot read the script " << options.script << "\n";
      return 2;
    }
    std::stringstream text;
    text << in.rdbuf();
    try {
      studio::run_script(frontend, text.str(), options.script);
    } catch (const studio::ScriptError& error) {
      std::cerr << "reconfig-studio: " << error.what() << "\n";
      return 1;
    }
  }
  for (int i = 0; i < options.frames; ++i) times.push_back(frontend.run_frame());
  if (!options.screenshot.empty()) save_screenshot(frontend, options.screenshot, !options.no_wait);
  if (!options.frame_times.empty() && !times.empty()) {
    const studio::FrameTimes stats = studio::summarize_frame_times(times);
    write_atomically(options.frame_times, [&](std::ostream& out) {
      out << fmt::format(R"({{"frames": {}, "width": {}, "height": {}, "mean_ms": {:.3f}, "median_ms": {:.3f}, )"
                         R"("p95_ms": {:.3f}, "max_ms": {:.3f}}})",
                         stats.frames, width, height, stats.mean, stats.median, stats.p95, stats.max)
          << "\n";
    });
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Reconfig Studio: edit reconfigurables and see their collisions as you edit"};
  Options options;
  app.add_option("scene", options.scene, "scene file (.json) to open");
  app.add_flag("--headless", options.headless, "no window: draw through EGL offscreen");
  app.add_flag("--window", options.window, "a window even with --frames/--screenshot (checks the window path)");
  app.add_option("--size", options.size, "window or image size WIDTHxHEIGHT")->capture_default_str();
  app.add_option("--screenshot", options.screenshot,
                 "save the last frame as PNG and exit (headless), once collision detection has finished");
  app.add_flag("--no-wait", options.no_wait, "take the --screenshot at once, while collisions may still be detected");
  app.add_option("--frames", options.frames, "frames to run before the screenshot (headless)");
  app.add_option("--script", options.script, "replay UI actions from this file (headless); see docs/studio.md");
  app.add_option("--frame-times", options.frame_times, "write frame time statistics of --frames as JSON");
  app.add_option("--time", options.time, "start at this time of the first transition");
  app.add_flag("--ghosts", options.ghosts, "show ghosts of moving parts");
  app.add_flag("--allow-outside-paths", options.studio.load.allow_outside_paths,
               "let scenes read meshes outside their folder (absolute paths, \"..\", symbolic links out)");
  collision::DetectorOptions& detector = options.studio.collisions.detector;
  app.add_option("--tolerance", detector.tolerance,
                 "collision settings (of designs that save none): largest distance between proxy and true motion")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--dop", options.dop,
                 "collision settings (of designs that save none): k-DOP family of the spacetime hierarchies")
      ->check(CLI::IsMember(scene::kDopHalfspaces))
      ->capture_default_str();
  app.add_option("--box-resolution", detector.box_resolution,
                 "collision settings (of designs that save none): grid of the collision boxes, a fraction of the "
                 "smaller part's size (0: exact)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  app.add_flag("--conservative", detector.conservative,
               "collision settings (of designs that save none): also report near misses the true motion may "
               "turn into collisions");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? 0 : 2;
  }
  detector.dop = *collision::dop_family(options.dop);  // --dop is checked to be one of scene::kDopHalfspaces
  int width = 0, height = 0;
  char x = 0;
  std::istringstream size(options.size);
  if (!(size >> width >> x >> height) || x != 'x' || width < 64 || height < 64 || width > 8192 || height > 8192) {
    std::cerr << "reconfig-studio: --size must look like 1280x800 (64 to 8192 pixels each way)\n";
    return 2;
  }
  const bool headless = !options.window && (options.headless || !options.screenshot.empty() ||
                                            !options.script.empty() || options.frames > 0);
  try {
    if (headless) return run_headless(options, width, height);
    studio::run_in_window(options.studio, options.scene.empty() ? std::nullopt : std::optional(options.scene), width,
                          height, options.frames, options.screenshot);
  } catch (const render::ContextError& error) {
    std::cerr << "reconfig-studio: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "reconfig-studio: " << error.what() << "\n";
    return 2;
  }
  return 0;
}
