// Studio frame time under Mesa's software renderer (llvmpipe), headless through EGL: the whole
// UI (panels, 3D viewport, ImGui drawing) per frame, finished on the GL side (glFinish).
//
//   build/bin/bench_studio [--frames N] [--size WxH] [--json] [--pip-only]
//
// Scenes: the bench-table example (176 triangles) and bunny through armadillo (127 K triangles,
// the collision benchmark's scene, saved as a scene file). For the big scene, frames are timed
// while the collision service detects in the background (the designer plays the transition right
// after opening it), then again once detection is done. Playback changes the time every frame,
// so every frame redraws the 3D view. On the kitchen, frames are timed with the
// picture-in-picture searching a new view every 12 frames (cycling over the transition's
// collisions) on its own thread, against the same searches done in the frame (as before that
// thread) and no picture at all.

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "frame_times.h"
#include "frontend.h"
#include "reconfig/resolve/interval_energy.h"
#include "reconfig/scene/scene_file.h"
#include "scenes.h"

namespace {

using namespace reconfig;
namespace fs = std::filesystem;

struct Stats {
  std::string scene, phase;
  int triangles = 0;
  studio::FrameTimes times;
  bool detecting_throughout = false;
  studio::FrameTimes every_12th;  ///< PIP phases: the frames that start a search (none: those frames)
};

Stats measure(studio::HeadlessFrontend& frontend, int frames, bool while_detecting) {
  studio::Studio& studio = frontend.studio();
  std::vector<double> times;
  studio.set_time(0);
  studio.toggle_play();
  bool detecting = true;
  for (int i = 0; i < frames; ++i) {
    if (!studio.playing()) {
      studio.set_time(0);
      studio.toggle_play();
    }
    times.push_back(frontend.run_frame());
    const auto snapshot = studio.collisions();
    detecting = detecting && !(snapshot->complete && snapshot->version == studio.document()->version());
    if (while_detecting && !detecting) break;
  }
  Stats stats;
  stats.times = studio::summarize_frame_times(times);
  stats.detecting_throughout = detecting;
  return stats;
}

// Keeps a result the compiler could otherwise drop.
void benchmark_keep(const view::Camera& camera) {
  static volatile double sink = 0;
  sink = sink + camera.distance;
}

enum class Pip { none, searched_in_frame, searched_on_its_thread };

// Plays the open transition for `frames` frames; every 12th, the PIP looks for the view of the
// next collision interval of the transition.
Stats measure_pip(studio::HeadlessFrontend& frontend, int frames, Pip pip) {
  studio::Studio& studio = frontend.studio();
  std::vector<collision::CollisionInterval> intervals;
  for (const auto& t : studio.collisions()->transitions)
    if (t.transition == studio.active_transition()) intervals = t.intervals;
  if (intervals.empty()) throw std::runtime_error("bench_studio: the kitchen's transition has no collisions");
  std::vector<double> times, search_times;
  studio.set_time(0);
  studio.toggle_play();
  for (int i = 0; i < frames; ++i) {
    if (!studio.playing()) {
      studio.set_time(0);
      studio.toggle_play();
    }
    const bool search = pip != Pip::none && i % 12 == 0;
    const collision::CollisionInterval& interval = intervals[(i / 12) % intervals.size()];
    const auto start = std::chrono::steady_clock::now();
    if (search && pip == Pip::searched_in_frame) {  // as the PIP did before its thread
      resolve::ShapeCache shapes;
      const double time = resolve::interval_energy(studio.document()->scene(), shapes, studio.active_transition(),
                                                   interval).severity_time;
      benchmark_keep(studio.best_view_camera(studio.active_transition(), interval, time));
    }
    if (search && pip == Pip::searched_on_its_thread) studio.pip().open_on(studio, studio.active_transition(), interval);
    frontend.run_frame();
    times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    if (i % 12 == 0) search_times.push_back(times.back());
  }
  if (studio.playing()) studio.toggle_play();
  studio.pip().close();
  Stats stats;
  stats.times = studio::summarize_frame_times(times);
  stats.every_12th = studio::summarize_frame_times(search_times);
  return stats;
}

int triangles(const scene::Reconfigurable& scene) {
  int count = 0;
  for (const auto& part : scene.parts) count += static_cast<int>(part.mesh.F.rows());
  return count;
}

}  // namespace

int main(int argc, char** argv) {
  int frames = 120, width = 1280, height = 800;
  bool json = false, pip_only = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--frames") && i + 1 < argc) frames = std::max(1, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--size") && i + 1 < argc) std::sscanf(argv[++i], "%dx%d", &width, &height);
    else if (!std::strcmp(argv[i], "--json")) json = true;
    else if (!std::strcmp(argv[i], "--pip-only")) pip_only = true;  // only the kitchen's PIP phases
    else {
      std::cerr << "usage: bench_studio [--frames N] [--size WxH] [--json] [--pip-only]\n";
      return 2;
    }
  }
  std::vector<Stats> results;
  if (!pip_only) {
    studio::HeadlessFrontend frontend(width, height);
    const fs::path file = fs::path(RECONFIG_SOURCE_DIR) / "examples" / "bench-table" / "scene.json";
    if (!frontend.studio().open(file)) throw std::runtime_error(frontend.studio().status());
    frontend.run_until_collisions_current(std::chrono::minutes(1));
    Stats stats = measure(frontend, frames, false);
    stats.scene = "bench-table";
    stats.phase = "playing";
    stats.triangles = triangles(frontend.studio().document()->scene());
    results.push_back(stats);
  }
  if (!pip_only) {
    // The big scene as a file, the way a designer opens it.
    const fs::path dir = fs::temp_directory_path() / "reconfig-bench-studio";
    fs::remove_all(dir);
    fs::create_directories(dir);
    scene::Reconfigurable big = bench::sweep_scene("armadillo.off", "bunny00.off");
    scene::save_scene(big, dir / "scene.json");
    studio::HeadlessFrontend frontend(width, height);
    if (!frontend.studio().open(dir / "scene.json")) throw std::runtime_error(frontend.studio().status());
    frontend.run_frame();
    Stats detecting = measure(frontend, frames, true);
    detecting.scene = "bunny through armadillo";
    detecting.phase = "playing while detection runs";
    detecting.triangles = triangles(frontend.studio().document()->scene());
    results.push_back(detecting);
    if (!frontend.run_until_collisions_current(std::chrono::minutes(10)))
      std::cerr << "bench_studio: detection did not finish within 10 minutes\n";
    Stats done = measure(frontend, frames, false);
    done.scene = detecting.scene;
    done.phase = "playing, detection done";
    done.triangles = detecting.triangles;
    results.push_back(done);
  }
  {
    studio::HeadlessFrontend frontend(width, height);
    const fs::path file = fs::path(RECONFIG_SOURCE_DIR) / "examples" / "kitchen" / "scene.json";
    if (!frontend.studio().open(file)) throw std::runtime_error(frontend.studio().status());
    frontend.studio().open_transition(frontend.studio().document()->scene().find_transition("open_hasty"));
    frontend.run_until_collisions_current(std::chrono::minutes(1));
    const std::pair<Pip, const char*> phases[] = {{Pip::none, "playing, no PIP"},
                                                  {Pip::searched_in_frame, "PIP view searched in the frame"},
                                                  {Pip::searched_on_its_thread, "PIP view searched on its thread"}};
    for (const auto& [pip, phase] : phases) {
      Stats stats = measure_pip(frontend, frames, pip);
      stats.scene = "kitchen (open_hasty)";
      stats.phase = phase;
      stats.phase += fmt::format(" (every 12th frame: median {:.1f} ms)", stats.every_12th.median);
      stats.triangles = triangles(frontend.studio().document()->scene());
      results.push_back(stats);
    }
  }
  if (json) {
    std::cout << "[\n";
    for (std::size_t i = 0; i < results.size(); ++i) {
      const Stats& s = results[i];
      std::cout << fmt::format(
          R"(  {{"scene": "{}", "phase": "{}", "triangles": {}, "width": {}, "height": {}, "frames": {}, )"
          R"("mean_ms": {:.2f}, "median_ms": {:.2f}, "p95_ms": {:.2f}, "max_ms": {:.2f}, "detecting_throughout": {}}}{})",
          s.scene, s.phase, s.triangles, width, height, s.times.frames, s.times.mean, s.times.median, s.times.p95,
          s.times.max,
          s.detecting_throughout, i + 1 < results.size() ? "," : "") << "\n";
    }
    std::cout << "]\n";
  } else {
    std::cout << fmt::format("studio frame time, {}x{} (target: <= 33 ms while detection runs)\n", width, height);
    std::cout << fmt::format("{:<26} {:<66} {:>9} {:>7} {:>9} {:>9} {:>9}\n", "scene", "phase", "triangles",
                             "frames", "median", "p95", "max");
    for (const Stats& s : results)
      std::cout << fmt::format("{:<26} {:<66} {:>9} {:>7} {:>6.1f} ms {:>6.1f} ms {:>6.1f} ms\n", s.scene, s.phase,
                               s.triangles, s.times.frames, s.times.median, s.times.p95, s.times.max);
  }
  return 0;
}
