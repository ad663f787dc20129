// View selection (reconfigurables §4.3): the best view of a collision interval, by occlusion
// queries over 1000 random directions (plus the axis views), headless with Mesa's software
// renderer. Targets: ≤ 150 ms on the kitchen, ≤ 1 s on the 1 M-triangle gallery.
//
//   build/bin/bench_view [--benchmark_filter=...]

#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <memory>
#include <mutex>

#include "reconfig/collision/detect_collisions.h"
#include "reconfig/render/best_view.h"
#include "reconfig/render/egl_context.h"
#include "reconfig/scene/scene_file.h"
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

render::EglContext& context() {
  static render::EglContext instance;
  return instance;
}

void BM_MonteCarloView(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  context().make_current();
  render::OcclusionCounter counter(64);
  render::BestView view;
  for (auto _ : state) benchmark::DoNotOptimize(view = render::best_view(counter, f.scene, f.request));
  state.SetLabel(f.label + ", " + std::to_string(f.triangles) + " triangles, " + std::to_string(view.candidates) +
                 " views, visible " + std::to_string(view.pixels.visible) + "/" + std::to_string(view.pixels.total) +
                 " px on " + context().renderer());
}
BENCHMARK(BM_MonteCarloView)->Arg(kKitchenHasty)->Arg(kGallery)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
