// View selection (reconfigurables §4.3): the best view of a collision interval, by occlusion
// counts over 1000 random directions (plus the axis views), headless with Mesa's software
// renderer. Targets: ≤ 150 ms on the kitchen, ≤ 1 s on the 1 M-triangle gallery.
// BM_MonteCarloView counts only the views that could beat the best (by their coverage);
// BM_EveryViewCounted counts all of them, the cost when none can be ruled out.
//
//   build/bin/bench_view [--benchmark_filter=...]

#include <benchmark/benchmark.h>

#include <ctime>

#include <filesystem>
#include <map>
#include <memory>
#include <mutex>

#include "reconfig/collision/detect_collisions.h"
#include "reconfig/render/best_view.h"
#include "reconfig/render/egl_context.h"
#include "reconfig/scene/scene_file.h"
#include "reconfig/view/box_view_camera.h"
#include "reconfig/view/scene_bounds.h"
#include "reconfig/view/view_candidates.h"
#include "scenes.h"

namespace {

using namespace reconfig;

enum SceneId : int { kKitchenHasty, kGallery };

struct Fixture {
  std::string label;
  scene::Reconfigurable scene;
  render::BestViewRequest request;
  long triangles = 0;
};

const Fixture& fixture(int which) {
  static std::map<int, Fixture> cache;
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  if (auto it = cache.find(which); it != cache.end()) return it->second;
  Fixture f;
  if (which == kKitchenHasty) {
    f.label = "kitchen, open_hasty";
    f.scene = scene::load_scene(std::filesystem::path(RECONFIG_SOURCE_DIR) / "examples" / "kitchen" / "scene.json");
    f.request.transition = f.scene.find_transition("open_hasty");
  } else {
    f.label = "gallery";
    f.scene = bench::gallery_scene();
  }
  collision::CollisionRequest detect;
  detect.transitions = {f.request.transition};
  const collision::CollisionResult found = collision::detect_collisions(f.scene, detect);
  const collision::CollisionInterval& ci = found.transitions.front().intervals.at(0);
  f.request.t0 = ci.t0;
  f.request.t1 = ci.t1;
  f.request.time = 0.5 * (ci.t0 + ci.t1);
  f.request.parts = ci.parts;
  f.request.box = ci.box;
  f.request.always_sample = true;
  for (const scene::Part& part : f.scene.parts) f.triangles += part.mesh.F.rows();
  return cache.emplace(which, std::move(f)).first->second;
}

// CPU seconds of every thread of the process (llvmpipe rasterizes on threads of its own): on
// a loaded machine the wall time waits for cores, this does not.
double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void report_process_cpu(benchmark::State& state, double start) {
  state.counters["cpu_all_threads_ms"] =
      benchmark::Counter(1e3 * (process_cpu_seconds() - start) / static_cast<double>(state.iterations()));
}

render::EglContext& context() {
  static render::EglContext instance;
  return instance;
}

void BM_MonteCarloView(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  context().make_current();
  render::OcclusionCounter counter(64);
  render::BestView view;
  const double start = process_cpu_seconds();
  for (auto _ : state) benchmark::DoNotOptimize(view = render::best_view(counter, f.scene, f.request));
  report_process_cpu(state, start);
  state.SetLabel(f.label + ", " + std::to_string(f.triangles) + " triangles, " + std::to_string(view.candidates) +
                 " views (" + std::to_string(view.counted) + " counted), visible " + std::to_string(view.pixels.visible) + "/" + std::to_string(view.pixels.total) +
                 " px on " + context().renderer());
}
BENCHMARK(BM_MonteCarloView)->Arg(kKitchenHasty)->Arg(kGallery)->Unit(benchmark::kMillisecond)->UseRealTime();

// The occluders and cameras best_view uses (but the floor), every camera counted.
void BM_EveryViewCounted(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  const render::BestViewRequest& request = f.request;
  context().make_current();
  const double min_radius =
      0.02 * view::scene_bounds_at(f.scene, request.transition, request.time).diagonal().norm();
  Eigen::MatrixX3d V;
  Eigen::MatrixX3i F;
  render::posed_occluders(f.scene, request.transition, request.time, request.parts, request.max_triangles, V, F,
                          request.box.center(), view::box_view_distance(request.box, request.fov_y, min_radius));
  std::vector<Eigen::Vector3d> directions = view::axis_view_directions(request.ground);
  for (const Eigen::Vector3d& d : view::random_view_directions(request.samples, request.ground, request.seed))
    directions.push_back(d);
  std::vector<view::Camera> cameras;
  for (const Eigen::Vector3d& d : directions)
    cameras.push_back(view::box_view_camera(request.box, d, 1.0, request.fov_y, min_radius));
  render::OcclusionCounter counter(64);
  counter.set_occluders(V, F);
  const double start = process_cpu_seconds();
  for (auto _ : state) benchmark::DoNotOptimize(counter.count(request.box, cameras, false));
  report_process_cpu(state, start);
  state.SetLabel(f.label + ", " + std::to_string(F.rows()) + " occluder triangles, " +
                 std::to_string(cameras.size()) + " views");
}
BENCHMARK(BM_EveryViewCounted)->Arg(kKitchenHasty)->Arg(kGallery)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
